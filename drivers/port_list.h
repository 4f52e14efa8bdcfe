#pragma once
// `rb ports`: the serial ports of this system and what is known of each, through libserialport
// (USB vendor, product and serial number, Bluetooth address, the driver's description), with
// the number `--port N` / `rCommPort N` maps to (port_names.h). Bluetooth RFCOMM bindings
// (/dev/rfcommN, made by `rfcomm bind`) are listed too: they are not in sysfs, where
// libserialport looks.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "port_names.h"

namespace rb::drivers {

struct PortInfo {
  std::string device;       ///< /dev/ttyUSB0
  std::string transport;    ///< "usb", "bluetooth", "native" (a UART, a pty, ...), "rfcomm"
  std::string description;  ///< the driver's words, when it has any
  int vid = -1, pid = -1;   ///< USB vendor and product id (-1: not USB, or not known)
  std::string manufacturer, product, serial;  ///< USB strings, when known
  std::string bluetoothAddress;
  std::optional<int64_t> number;  ///< the --port number that opens it (none: only its path)
};

/// Every serial port libserialport finds, plus the RFCOMM bindings under `devDir`, sorted by
/// device, with their --port numbers (under `devDir`). Throws RuntimeError when libserialport
/// cannot list them.
std::vector<PortInfo> listPorts(PortScheme scheme = nativePortScheme(),
                                const std::string& devDir = "/dev");

/// What libserialport knows of one device (any path: a pty works too); the transport is
/// "unknown" when libserialport does not know the device.
PortInfo describePort(const std::string& device, PortScheme scheme = nativePortScheme(),
                      const std::string& devDir = "/dev");

/// The RFCOMM bindings under `devDir` (rfcomm0, rfcomm1, ...), sorted.
std::vector<std::string> rfcommDevices(const std::string& devDir = "/dev");

/// The smallest N that --port N opens `device` with (devicePathForPort), checking 1 to 256.
std::optional<int64_t> portNumberOf(const std::string& device, PortScheme scheme,
                                    const std::string& devDir);

/// The table rb ports prints: one line per port ("--port  device  what"), a header first;
/// "no serial ports found" when there are none.
std::string formatPorts(const std::vector<PortInfo>& ports);

}  // namespace rb::drivers
