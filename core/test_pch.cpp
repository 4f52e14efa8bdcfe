// Nothing to compile: this target exists to precompile Catch2's header for the test programs
// (rb_test_pch in the top-level CMakeLists.txt).
