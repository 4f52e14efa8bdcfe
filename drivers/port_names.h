#pragma once
// How a RobotBASIC port number (rCommPort 5, --port 5: Windows' COM5) maps to a device on
// this system, and how --port's text is read. docs/real-robot.md states the same rules.
//
//   Linux: COM n is the first of /dev/rfcomm(n-1), /dev/ttyUSB(n-1), /dev/ttyACM(n-1),
//          /dev/ttyS(n-1) that exists (COM1 = ttyS0, as Wine and every Linux serial guide
//          count).
//   macOS: COM n is the n-th /dev/cu.* device in sorted order (cu.*, not tty.*: opening a
//          cu device does not wait for a carrier).

#include <cstdint>
#include <string>

namespace rb::drivers {

/// The two numbering rules above.
enum class PortScheme { Linux, MacOS };

/// The scheme of the system rb was built for.
PortScheme nativePortScheme();

/// The device for port number `n` (>= 1) under `devDir`. Throws RuntimeError listing what was
/// looked for when no device matches.
std::string devicePathForPort(int64_t n, PortScheme scheme = nativePortScheme(),
                              const std::string& devDir = "/dev");

/// --port's text: a number ("5") or "COM5" (any case) maps through devicePathForPort; anything
/// else is a device path used as it is.
std::string resolvePortOption(const std::string& text, PortScheme scheme = nativePortScheme(),
                              const std::string& devDir = "/dev");

}  // namespace rb::drivers
