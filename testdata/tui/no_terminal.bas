// rb run --tui needs a terminal: without one (here standard input is a pipe) it says so and
// exits 74 before running anything.
// args: --tui
// exit: 74
// expect-stderr: rb run --tui: no terminal (standard input and output must be a terminal); run without --tui for a headless run
print "not reached"
