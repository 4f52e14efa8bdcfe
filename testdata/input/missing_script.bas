// An events file that does not exist: exit 66, as for a missing program.
// args: --events no_such_file.events
// exit: 66
// expect-stderr: rb run: cannot read events file 'no_such_file.events'
print "not reached"
