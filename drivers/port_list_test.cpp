#include "port_list.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "pty.h"

using namespace rb::drivers;
namespace fs = std::filesystem;

namespace {
/// A fake /dev with the named (empty) device files.
struct FakeDev {
  fs::path dir;
  explicit FakeDev(std::initializer_list<const char*> names) {
    dir = fs::temp_directory_path() / ("rb-ports-" + std::to_string(::getpid()) + "-" +
                                       std::to_string(reinterpret_cast<uintptr_t>(this)));
    fs::create_directories(dir);
    for (const char* n : names) std::ofstream(dir / n).put('\0');
  }
  ~FakeDev() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  std::string at(const char* name) const { return (dir / name).string(); }
};
}  // namespace

TEST_CASE("ports: RFCOMM bindings and --port numbers in a fake device tree", "[ports]") {
  FakeDev dev({"ttyS0", "ttyS1", "ttyUSB1", "rfcomm0", "rfcomm2", "rfcommx", "ttyACM0"});
  auto rf = rfcommDevices(dev.dir.string());
  REQUIRE(rf.size() == 2);
  CHECK(rf[0] == dev.at("rfcomm0"));
  CHECK(rf[1] == dev.at("rfcomm2"));
  // COM n is the first of rfcomm(n-1), ttyUSB(n-1), ttyACM(n-1), ttyS(n-1) that exists.
  CHECK(portNumberOf(dev.at("rfcomm0"), PortScheme::Linux, dev.dir.string()) == 1);
  CHECK(portNumberOf(dev.at("ttyUSB1"), PortScheme::Linux, dev.dir.string()) == 2);
  CHECK(portNumberOf(dev.at("rfcomm2"), PortScheme::Linux, dev.dir.string()) == 3);
  // Shadowed by rfcomm0 (COM1): only its path opens it.
  CHECK_FALSE(portNumberOf(dev.at("ttyS0"), PortScheme::Linux, dev.dir.string()));
  CHECK_FALSE(portNumberOf(dev.at("ttyACM0"), PortScheme::Linux, dev.dir.string()));
}

TEST_CASE("ports: the table", "[ports]") {
  CHECK(formatPorts({}) == "no serial ports found\n");
  PortInfo usb;
  usb.device = "/dev/ttyUSB0";
  usb.transport = "usb";
  usb.vid = 0x0403;
  usb.pid = 0x6001;
  usb.manufacturer = "FTDI";
  usb.product = "FT232R USB UART";
  usb.serial = "A50285BI";
  usb.number = 1;
  PortInfo rf;
  rf.device = "/dev/rfcomm1";
  rf.transport = "rfcomm";
  rf.number = 2;
  PortInfo uart;
  uart.device = "/dev/ttyS0";
  uart.transport = "native";
  uart.description = "ttyS0";  // the device's name again: not shown
  PortInfo bt;
  bt.device = "/dev/ttyBT0";
  bt.transport = "bluetooth";
  bt.bluetoothAddress = "00:12:6f:aa:bb:cc";
  bt.description = "RB-9 serial";
  std::string t = formatPorts({usb, rf, uart, bt});
  CHECK(t ==
        "--port  device        what\n"
        "1       /dev/ttyUSB0  USB 0403:6001, FTDI FT232R USB UART, serial A50285BI\n"
        "2       /dev/rfcomm1  Bluetooth RFCOMM binding (rfcomm bind)\n"
        "-       /dev/ttyS0    serial port\n"
        "-       /dev/ttyBT0   Bluetooth 00:12:6f:aa:bb:cc, RB-9 serial\n");
}

TEST_CASE("ports: a pseudo-terminal described, the system's list read", "[ports]") {
  Pty pty;
  PortInfo p = describePort(pty.slavePath());
  CHECK(p.device == pty.slavePath());
  CHECK_FALSE(p.transport.empty());
  CHECK(formatPorts({p}).find(pty.slavePath()) != std::string::npos);
  // Whatever this machine has: listing never throws on a system with sysfs.
  std::vector<PortInfo> all;
  CHECK_NOTHROW(all = listPorts());
  for (const PortInfo& i : all) CHECK_FALSE(i.device.empty());
}
