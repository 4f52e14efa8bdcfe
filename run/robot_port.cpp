#include "robot_port.h"

#include "port_names.h"
#include "base/runtime_error.h"
#include "serial_link.h"

namespace rb::run {

std::unique_ptr<RobotLink> openRobotPort(std::optional<int64_t> programPort, const RunOptions& opts) {
  if (opts.noPorts)
    throw RuntimeError((programPort ? "rCommPort " + std::to_string(*programPort) : std::string("--real")) +
                       ": a program graded by rb test opens no serial port unless the assignment allows it "
                       "(ports = true)");
  std::string path;
  if (!opts.port.empty()) {
    path = drivers::resolvePortOption(opts.port);
  } else if (!programPort) {
    throw RuntimeError("--real needs --port: the robot's serial port, a number (5 = COM5) or a device path");
  } else {
    path = drivers::devicePathForPort(*programPort);
  }
  drivers::SerialLinkOptions link;
  link.baud = opts.baud;
  link.timeoutSeconds = opts.robotTimeoutSeconds;
  return std::make_unique<drivers::SerialLink>(path, link);
}

}  // namespace rb::run
