// The serial driver end to end over a pseudo-terminal: the emulator (or a scripted robot) on
// the master side, SerialLink on the slave side as it would open a Bluetooth port. Every fault
// must end in an error naming the port, within its time bound.
#include <catch2/catch.hpp>

#include <poll.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "emulator_server.h"
#include "pty.h"
#include "robot_emulator.h"
#include "base/runtime_error.h"
#include "serial_link.h"

using namespace rb;
using namespace rb::drivers;
using Clock = std::chrono::steady_clock;

namespace {

/// An emulator serving a fresh pty on a thread of its own for the length of a test.
class EmulatorThread {
 public:
  explicit EmulatorThread(EmulatorOptions options = {}, int latencyMs = 0) : emulator_(options) {
    ServeOptions serve;
    serve.latencyMs = latencyMs;
    thread_ = std::thread([this, serve] {
      end_ = serveRobot(pty_, emulator_, serve, [this] { return stop_.load(); });
    });
  }
  ~EmulatorThread() {
    stop_ = true;
    thread_.join();
  }
  const std::string& path() const { return pty_.slavePath(); }
  ServeEnd end() const { return end_; }

 private:
  Pty pty_;
  RobotEmulator emulator_;
  std::atomic<bool> stop_{false};
  ServeEnd end_ = ServeEnd::Stopped;
  std::thread thread_;
};

SerialLinkOptions quick(double timeout = 0.3) {
  SerialLinkOptions o;
  o.timeoutSeconds = timeout;
  return o;
}

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

TEST_CASE("a command goes out as two bytes and the five-byte reply comes back", "[serial]") {
  EmulatorThread robot;
  {
    SerialLink link(robot.path(), {});
    CHECK(link.name() == robot.path());
    CHECK(link.transact(66, 0).result == 400);
    link.transact(6, 120);
    CHECK(link.transact(66, 1).result == 180);
    link.transact(12, 90);
    CHECK(link.transact(24, 0).result == 90);
  }
  for (int baud : {1200, 115200}) {
    SerialLinkOptions o;
    o.baud = baud;
    CHECK_NOTHROW(SerialLink(robot.path(), o).transact(6, 0));
  }
}

TEST_CASE("no answer: a timeout error naming the port, on time", "[serial]") {
  EmulatorOptions o;
  o.dropEvery = 2;
  EmulatorThread robot(o);
  SerialLink link(robot.path(), quick());
  link.transact(6, 0);
  auto start = Clock::now();
  CHECK_THROWS_WITH(link.transact(6, 0), "robot on " + robot.path() + " did not answer within 0.3 s");
  CHECK(secondsSince(start) >= 0.29);
  CHECK(secondsSince(start) < 1.0);
  // The port was released at the fault; the link refuses further commands at once.
  CHECK_THROWS_WITH(link.transact(6, 0), Catch::Contains("disconnected after an earlier fault"));
}

TEST_CASE("an answer slower than the timeout is a timeout", "[serial]") {
  EmulatorThread robot({}, 600);
  SerialLink link(robot.path(), quick());
  CHECK_THROWS_WITH(link.transact(6, 0), Catch::Contains("did not answer within 0.3 s"));
}

TEST_CASE("short and garbled replies are errors naming the port", "[serial]") {
  SECTION("short") {
    EmulatorOptions o;
    o.shortEvery = 1;
    EmulatorThread robot(o);
    SerialLink link(robot.path(), quick());
    CHECK_THROWS_WITH(link.transact(6, 0), "robot on " + robot.path() +
                                               " sent a short reply: 2 of 5 bytes within 0.3 s (00 00)");
  }
  SECTION("garbled") {
    EmulatorOptions o;
    o.garbleEvery = 1;
    EmulatorThread robot(o);
    SerialLink link(robot.path(), quick());
    CHECK_THROWS_WITH(link.transact(6, 0),
                      Catch::StartsWith("robot on " + robot.path() + " sent a malformed reply"));
  }
}

TEST_CASE("the device going away mid-run is reported at once", "[serial]") {
  EmulatorOptions o;
  o.dieAfter = 2;
  EmulatorThread robot(o);
  SerialLink link(robot.path(), quick(5));
  link.transact(6, 0);
  link.transact(6, 0);
  auto start = Clock::now();
  CHECK_THROWS_WITH(link.transact(6, 0),
                    "lost the connection to the robot on " + robot.path() + ": the device hung up");
  CHECK(secondsSince(start) < 2);
}

TEST_CASE("a port is exclusive while open and free again once closed", "[serial]") {
  EmulatorThread robot;
  {
    SerialLink first(robot.path(), {});
    CHECK_THROWS_WITH(SerialLink(robot.path(), {}), Catch::Contains("robot port " + robot.path() + " is busy"));
    first.transact(6, 0);
  }
  SerialLink again(robot.path(), {});
  CHECK_NOTHROW(again.transact(6, 0));
}

TEST_CASE("ports that cannot be opened say why", "[serial]") {
  CHECK_THROWS_WITH(SerialLink("/nonexistent/robot", {}),
                    "cannot open robot port /nonexistent/robot: no such device");
  auto file = std::filesystem::temp_directory_path() / ("rb-not-a-tty-" + std::to_string(::getpid()));
  std::ofstream(file) << "x";
  CHECK_THROWS_WITH(SerialLink(file.string(), {}), Catch::Contains("it is not a serial device"));
  std::filesystem::remove(file);
  SerialLinkOptions o;
  o.baud = 12345;
  CHECK_THROWS_WITH(SerialLink("/dev/null", o), Catch::Contains("12345 baud: not a standard rate"));
}

TEST_CASE("stale bytes waiting before a command are not taken for its reply", "[serial]") {
  Pty pty;
  SerialLink link(pty.slavePath(), quick(2));
  const uint8_t stale[5] = {1, 1, 1, 1, 1};
  REQUIRE(::write(pty.master(), stale, 5) == 5);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // let them reach the port
  std::thread robot([&] {
    uint8_t cmd[2];
    size_t got = 0;
    while (got < 2) {
      pollfd p{pty.master(), POLLIN, 0};
      ::poll(&p, 1, 1000);
      ssize_t n = ::read(pty.master(), cmd + got, 2 - got);
      if (n > 0) got += static_cast<size_t>(n);
    }
    const uint8_t reply[5] = {0, 0, 0, 0x01, 0x2c};
    (void)!::write(pty.master(), reply, 5);
  });
  RobotReply r = link.transact(6, 0);
  robot.join();
  CHECK(r.feel == 0);
  CHECK(r.result == 300);
}

TEST_CASE("the emulator serves one client after another", "[serial]") {
  EmulatorThread robot;
  for (int i = 0; i < 3; ++i) {
    SerialLink link(robot.path(), {});
    CHECK(link.transact(66, 0).result == 400);
  }
}
