// An included library runs as if its text were here.
#include "lib/helpers.bas"
gosub Greet // expect: hello from the library
print Twice(4) // expect: 8
