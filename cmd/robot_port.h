#pragma once
// Opening the serial link to a real robot from the command line's options: how a port number
// maps to a device, the baud rate, the answer timeout.

#include <memory>
#include <string>

#include "robot_link.h"
#include "run_command.h"

namespace rb::cli {

/// Opens the robot for `rCommPort port` (or --real): the --port option wins over the program's
/// number. Throws RuntimeError with a clear message when the port cannot be opened.
std::unique_ptr<RobotLink> openRobotPort(int64_t port, const RunOptions& opts);

}  // namespace rb::cli
