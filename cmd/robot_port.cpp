#include "robot_port.h"

#include "runtime_error.h"

namespace rb::cli {

std::unique_ptr<RobotLink> openRobotPort(int64_t port, const RunOptions&) {
  throw RuntimeError("rCommPort " + std::to_string(port) + ": real robots are not supported in this build yet");
}

}  // namespace rb::cli
