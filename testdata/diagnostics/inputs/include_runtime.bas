// nontest: a runtime error inside an included sub (diagnostics/run.t)
#include "lib_runtime.bas"
print Half(4)
