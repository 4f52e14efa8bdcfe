#pragma once
// Opening the serial link to a real robot from the command line's options: how a port number
// maps to a device (drivers/port_names.h), the baud rate, the answer timeout.

#include <cstdint>
#include <memory>
#include <string>

#include "robot/robot_link.h"
#include "run_command.h"

namespace rb::cli {

/// Opens the robot for `rCommPort port` (or --real, which passes -1): a non-empty --port wins
/// over the program's number. Throws RuntimeError with a clear message naming the port when it
/// cannot be opened, and when --real comes without --port.
std::unique_ptr<RobotLink> openRobotPort(int64_t port, const RunOptions& opts);

}  // namespace rb::cli
