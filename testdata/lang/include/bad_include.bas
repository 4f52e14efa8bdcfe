// Errors inside an included file point at that file and line.
#include "lib/broken.bas"
print 1
