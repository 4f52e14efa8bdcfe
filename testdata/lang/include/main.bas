// #include inserts a file where it stands, each file once; diagnostics name the included file.
#include "lib/helpers.bas"
#include "lib/helpers.bas"
#include "LIB/Helpers.BAS"
gosub Greet // expect: hello from the library
print Twice(21) // expect: 42
#include "missing.bas" // expect-error: include file 'missing.bas' not found
