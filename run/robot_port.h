#pragma once
// Opening the serial link to a real robot from the command line's options: how a port number
// maps to a device (drivers/port_names.h), the baud rate, the answer timeout.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "robot/robot_link.h"
#include "run_options.h"

namespace rb::run {

/// Opens the robot's serial link. `programPort` is the number of a program's `rCommPort`, or
/// nullopt for --real: the port --port names. A non-empty --port wins over the program's number.
/// Throws RuntimeError with a clear message naming the port when it cannot be opened, and when
/// --real comes without --port.
std::unique_ptr<RobotLink> openRobotPort(std::optional<int64_t> programPort, const RunOptions& opts);

}  // namespace rb::run
