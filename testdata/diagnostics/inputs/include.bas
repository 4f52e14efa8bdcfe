// nontest: an error inside an included file (diagnostics/check.t)
#include "lib_bad.bas"
print 1
