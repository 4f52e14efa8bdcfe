// Spawn runs other programs only when the user allows it (rb run --allow-spawn).
n = Spawn("echo hello", P_NOWAIT) // expect-runtime-error: Spawn: running other programs is not allowed; rb run --allow-spawn allows it
