// robot built-ins (filled in by the simulator and interaction work).
#include "builtins_impl.h"

namespace rb::builtins {

void appendRobotBuiltins(std::vector<Builtin>& /*table*/) {}

}  // namespace rb::builtins
