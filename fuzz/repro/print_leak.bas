// Not a fuzzer find: a leak in core/machine/interpreter.cpp's threaded dispatch (GCC build).
// NEXT is a computed goto that leaves each handler's block without running destructors, so
// locals such as `text` in the Print handler (interpreter.cpp:764) leak. Clang rejects the same
// code outright ("cannot jump from this indirect goto statement to one of its possible targets").
// Reproduce: scripts/build.sh --sanitize && build-asan/cmd/rb run fuzz/repro/print_leak.bas
// LeakSanitizer: "Direct leak of 144 byte(s) in 3 object(s)" from rb::formatItems via Interpreter::execute.
for i = 1 to 3
  print "this is a string longer than fifteen characters"
next
