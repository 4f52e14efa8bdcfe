// Port numbers to devices, on a made-up /dev.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "port_names.h"

using namespace rb::drivers;
namespace fs = std::filesystem;

namespace {

/// A temporary folder standing in for /dev, removed at the end of the test.
struct FakeDev {
  fs::path dir = fs::temp_directory_path() / ("rb-fake-dev-" + std::to_string(::getpid()));
  FakeDev() { fs::create_directories(dir); }
  ~FakeDev() { fs::remove_all(dir); }
  void add(const std::string& name) { std::ofstream(dir / name) << ""; }
};

}  // namespace

TEST_CASE("Linux: COM n is rfcomm, ttyUSB, ttyACM or ttyS number n-1, first found", "[ports]") {
  FakeDev dev;
  std::string d = dev.dir.string();
  CHECK_THROWS_WITH(devicePathForPort(5, PortScheme::Linux, d),
                    Catch::Contains("no serial device for port 5") && Catch::Contains("rfcomm4") &&
                        Catch::Contains("ttyS4") && Catch::Contains("--port PATH"));
  dev.add("ttyS4");
  CHECK(devicePathForPort(5, PortScheme::Linux, d) == d + "/ttyS4");
  dev.add("ttyUSB4");
  CHECK(devicePathForPort(5, PortScheme::Linux, d) == d + "/ttyUSB4");
  dev.add("rfcomm4");
  CHECK(devicePathForPort(5, PortScheme::Linux, d) == d + "/rfcomm4");
  dev.add("ttyS0");
  CHECK(devicePathForPort(1, PortScheme::Linux, d) == d + "/ttyS0");
  CHECK_THROWS_WITH(devicePathForPort(0, PortScheme::Linux, d), Catch::Contains("start at 1"));
}

TEST_CASE("macOS: COM n is the n-th cu.* device in sorted order", "[ports]") {
  FakeDev dev;
  std::string d = dev.dir.string();
  dev.add("cu.usbserial-A1");
  dev.add("cu.Bluetooth-Incoming-Port");
  dev.add("tty.usbserial-A1");
  dev.add("cu.RB9-SerialPort");
  CHECK(devicePathForPort(1, PortScheme::MacOS, d) == d + "/cu.Bluetooth-Incoming-Port");
  CHECK(devicePathForPort(2, PortScheme::MacOS, d) == d + "/cu.RB9-SerialPort");
  CHECK(devicePathForPort(3, PortScheme::MacOS, d) == d + "/cu.usbserial-A1");
  CHECK_THROWS_WITH(devicePathForPort(4, PortScheme::MacOS, d), Catch::Contains("has 3 cu.* devices"));
}

TEST_CASE("the port option takes a number, COMn or a path", "[ports]") {
  FakeDev dev;
  std::string d = dev.dir.string();
  dev.add("rfcomm4");
  CHECK(resolvePortOption("5", PortScheme::Linux, d) == d + "/rfcomm4");
  CHECK(resolvePortOption("COM5", PortScheme::Linux, d) == d + "/rfcomm4");
  CHECK(resolvePortOption("com5", PortScheme::Linux, d) == d + "/rfcomm4");
  CHECK(resolvePortOption("/tmp/robot", PortScheme::Linux, d) == "/tmp/robot");
  CHECK(resolvePortOption("robot5", PortScheme::Linux, d) == "robot5");
}
