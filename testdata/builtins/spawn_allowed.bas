// With --allow-spawn, Spawn runs a command line: any mode but P_NOWAIT waits for its exit status.
// args: --allow-spawn
print Spawn("exit 3", 0)
// expect: 3
print P_NOWAIT
// expect: 1
