// RealRobot and the wire protocol against an in-memory link that records every command and
// answers from a script: what goes on the wire for each robot statement, how replies are
// read, and how faults reach the program.
#include <catch2/catch.hpp>

#include <deque>
#include <memory>
#include <utility>
#include <vector>

#include "machine/machine.h"
#include "robot/protocol.h"
#include "robot/real_robot.h"
#include "base/runtime_error.h"
#include "machine/test_support.h"

using namespace rb;

namespace {

using Bytes = std::vector<std::pair<int, int>>;

/// What the fake saw and what it answers; shared with the test after the link is handed over.
struct FakeWire {
  Bytes sent;
  std::deque<RobotReply> replies;  ///< answered in order; an empty reply once they run out
  bool failNext = false;           ///< the next command fails as a timeout would
};

class FakeLink : public RobotLink {
 public:
  explicit FakeLink(std::shared_ptr<FakeWire> wire) : wire_(std::move(wire)) {}
  RobotReply transact(uint8_t code, uint8_t param) override {
    wire_->sent.emplace_back(code, param);
    if (wire_->failNext) throw RuntimeError("robot on fake did not answer within 2 s");
    if (wire_->replies.empty()) return {};
    RobotReply r = wire_->replies.front();
    wire_->replies.pop_front();
    return r;
  }
  std::string name() const override { return "fake"; }

 private:
  std::shared_ptr<FakeWire> wire_;
};

struct Rig {
  std::shared_ptr<FakeWire> wire = std::make_shared<FakeWire>();
  RealRobot robot{std::make_unique<FakeLink>(wire)};
};

RobotReply result(uint16_t v) {
  RobotReply r;
  r.result = v;
  return r;
}

/// A host whose rCommPort opens the fake link, so whole programs can drive it.
class FakeRobotHost : public test::TestHost {
 public:
  std::shared_ptr<FakeWire> wire = std::make_shared<FakeWire>();
  std::vector<int64_t> opened;
  std::unique_ptr<RobotLink> openRobot(int64_t port) override {
    opened.push_back(port);
    return std::make_unique<FakeLink>(wire);
  }
};

struct ProgramRun {
  std::string out, diagnostics;
  RunResult result;
};

ProgramRun runWith(FakeRobotHost& host, const std::string& text) {
  test::MemoryReader reader;
  reader.files["test.bas"] = text;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  auto program = compileProgram(*loaded, {}, diags);
  ProgramRun run;
  for (const Diagnostic& d : diags.all()) run.diagnostics += formatDiagnostic(loaded->sources, d);
  REQUIRE(program);
  Machine machine(host, 1);
  Interpreter interp(*program, machine);
  run.result = interp.run({});
  run.out = host.out;
  if (run.result.error) run.diagnostics += formatDiagnostic(loaded->sources, *run.result.error);
  return run;
}

}  // namespace

TEST_CASE("moves and turns: one command per 255, the odd code for negative", "[real]") {
  Rig r;
  r.robot.forward(10, {});
  CHECK(r.wire->sent == Bytes{{6, 10}});  // SERVO 2008's own example: rForward 10 -> 06 0A
  r.wire->sent.clear();
  r.robot.forward(600, {});
  CHECK(r.wire->sent == Bytes{{6, 255}, {6, 255}, {6, 90}});
  r.wire->sent.clear();
  r.robot.forward(-20, {});
  CHECK(r.wire->sent == Bytes{{7, 20}});
  r.wire->sent.clear();
  r.robot.turn(400, {});
  r.robot.turn(-90, {});
  CHECK(r.wire->sent == Bytes{{12, 255}, {12, 145}, {13, 90}});
  r.wire->sent.clear();
  r.robot.forward(0, {});  // still a command: programs use it to refresh the sensors
  r.robot.turn(0, {});
  CHECK(r.wire->sent == Bytes{{6, 0}, {12, 0}});
}

TEST_CASE("the dead-reckoned pose starts at the screen centre and follows the commands", "[real]") {
  Rig r;
  CHECK(r.robot.pose().pos.x() == 400);
  CHECK(r.robot.pose().pos.y() == 300);
  CHECK(r.robot.pose().heading == 0);
  r.robot.forward(100, {});
  r.robot.turn(90, {});
  r.robot.forward(50, {});
  CHECK(r.robot.pose().pos.x() == Approx(450));
  CHECK(r.robot.pose().pos.y() == Approx(200));
  CHECK(r.robot.pose().heading == Approx(90));
  r.robot.turn(-450, {});
  CHECK(r.robot.pose().heading == Approx(0));
  r.robot.locate(100, 200, 45, 20, 1);
  CHECK(r.wire->sent.back() == std::pair<int, int>(3, 0));
  CHECK(r.robot.pose().pos.x() == 100);
  CHECK(r.robot.pose().heading == 45);
}

TEST_CASE("amounts that are not numbers or absurdly large stop before anything is sent", "[real]") {
  Rig r;
  CHECK_THROWS_WITH(r.robot.forward(1e9, {}), Catch::Contains("too far for a real robot"));
  CHECK_THROWS_WITH(r.robot.turn(std::nan(""), {}), Catch::Contains("not a number"));
  CHECK(r.wire->sent.empty());
}

TEST_CASE("rFeel, rBumper and rSense read the latest reply, asking once if there is none", "[real]") {
  Rig r;
  RobotReply status;
  status.feel = 4;
  status.bumper = 2;
  status.sense = 1;
  r.wire->replies.push_back(status);
  CHECK(r.robot.feel() == 4);
  CHECK(r.wire->sent == Bytes{{6, 0}});  // the harmless status command
  CHECK(r.robot.bumper() == 2);
  CHECK(r.robot.sense() == 1);
  CHECK(r.wire->sent.size() == 1);  // no new command: the same reply
  RobotReply moved;
  moved.feel = 16;
  r.wire->replies.push_back(moved);
  r.robot.forward(5, {});
  CHECK(r.robot.feel() == 16);
  CHECK(r.robot.bumper() == 0);
}

TEST_CASE("sensor commands carry their parameter and return the 16-bit result", "[real]") {
  Rig r;
  for (uint16_t v : {123, 456, 4, 77, 359 + 360, 321, 222, 9})
    r.wire->replies.push_back(result(v));
  CHECK(r.robot.range(-45) == 123);
  CHECK(r.robot.range(300) == 456);  // 300 degrees right is 60 left
  CHECK(r.robot.look(10) == 4);
  CHECK(r.robot.beacon(4) == 77);
  CHECK(r.robot.compass() == 359);
  CHECK(r.robot.gpsX() == 321);
  CHECK(r.robot.gpsY() == 222);
  CHECK(r.robot.command(200, 7) == 9);
  CHECK(r.wire->sent ==
        Bytes{{193, 45}, {193, 60}, {48, 10}, {96, 4}, {24, 0}, {66, 0}, {66, 1}, {200, 7}});
  r.wire->sent.clear();
  r.robot.look(-0.2);  // rounds to 0: straight ahead is "right"
  r.robot.setPen(true);
  r.robot.setPen(false);
  r.robot.setSpeed(5);
  r.robot.setSpeed(1000);
  CHECK(r.wire->sent == Bytes{{48, 0}, {129, 1}, {129, 0}, {36, 5}, {36, 255}});
  CHECK_FALSE(r.robot.penDown());
}

TEST_CASE("rCommand checks its bytes and rChargeLevel has no command", "[real]") {
  Rig r;
  CHECK_THROWS_WITH(r.robot.command(256, 0), Catch::Contains("0..255"));
  CHECK_THROWS_WITH(r.robot.command(1, -1), Catch::Contains("0..255"));
  CHECK_THROWS_WITH(r.robot.chargeLevel(), Catch::Contains("no battery command"));
  CHECK(r.wire->sent.empty());
}

TEST_CASE("the reply layout decodes, encodes and rejects impossible bits", "[real][protocol]") {
  using namespace protocol;
  // Bumper, feel, sense, then the result high byte first (the SR15 RROS sketch's order).
  std::array<uint8_t, kReplySize> b{15, 31, 7, 0x01, 0x2c};
  RobotReply r = decodeReply(b);
  CHECK(r.bumper == 15);
  CHECK(r.feel == 31);
  CHECK(r.sense == 7);
  CHECK(r.result == 300);
  CHECK(encodeReply(r) == b);
  CHECK(plausibleReply(b));
  // What that firmware sends with the front bumper, the left infrared and the middle floor
  // sensor on: feel 16 is a left sensor, not a bumper bit no robot has.
  RobotReply sr15 = decodeReply({4, 16, 2, 0, 0});
  CHECK(sr15.bumper == 4);
  CHECK(sr15.feel == 16);
  CHECK(sr15.sense == 2);
  CHECK(plausibleReply({4, 16, 2, 0, 0}));
  CHECK_FALSE(plausibleReply({16, 0, 0, 0, 0}));  // a fifth bumper
  CHECK_FALSE(plausibleReply({0, 32, 0, 0, 0}));  // a sixth infrared sensor
  CHECK(plausibleReply({0, 0, 255, 255, 255}));  // sense is free for any data
  const uint8_t cmd[] = {6, 255};
  CHECK(hexBytes(cmd, 2) == "06 ff");
  CHECK(commandName(kCodes.rangeLeft) == "rRange (left)");
  CHECK(commandName(200).empty());
}

TEST_CASE("a program drives the robot through rCommPort with the port number it gives", "[real]") {
  FakeRobotHost host;
  ProgramRun run = runWith(host,
                           "rCommPort 5\n"
                           "rForward 600\n"
                           "rTurn -90\n"
                           "print rFeel()\n"
                           "print rCommand(200, 7)\n"
                           "rCommPort 0\n"
                           "print rCommand(200, 7)\n");
  CHECK(run.diagnostics.empty());
  CHECK(host.opened == std::vector<int64_t>{5});
  CHECK(host.wire->sent == Bytes{{6, 255}, {6, 255}, {6, 90}, {13, 90}, {200, 7}});
  CHECK(run.out == "0\n0\n0\n");  // after rCommPort 0, rCommand is the simulator's 0
}

TEST_CASE("a link fault stops the program at the statement, naming the port", "[real]") {
  FakeRobotHost host;
  host.wire->failNext = true;
  ProgramRun run = runWith(host, "rCommPort 5\nprint 1\nrForward 10\nprint 2\n");
  CHECK(run.out == "1\n");
  CHECK_THAT(run.diagnostics, Catch::StartsWith("test.bas:3:1: error: robot on fake did not answer within 2 s [rb-runtime-error]\n"));
}

TEST_CASE("Machine::robot() is the connected real robot, and the simulator again after rCommPort 0",
          "[real]") {
  FakeRobotHost host;
  Machine machine(host, 1);
  CHECK(&machine.robot() == &machine.simulator());
  machine.useCommPort(3);
  REQUIRE(machine.realRobot() != nullptr);
  CHECK(&machine.robot() == machine.realRobot());
  // Placing and driving the active robot moves the real robot's pose, not the simulator's.
  machine.robot().locate(100, 200, 90, 25, 4);
  machine.robot().forward(30, {});
  CHECK(machine.robot().located());
  CHECK(machine.robot().pose().pos.x() == Approx(130));
  CHECK(machine.robot().radius() == 25);
  CHECK(machine.robot().colour() == 4);
  CHECK_FALSE(machine.simulator().located());
  // Readings a live view shows come from the last reply; none are asked for.
  size_t sent = host.wire->sent.size();
  CHECK(machine.robot().quietReadings().has_value());
  CHECK(host.wire->sent.size() == sent);
  machine.useCommPort(0);
  CHECK(machine.realRobot() == nullptr);
  CHECK(&machine.robot() == &machine.simulator());
  CHECK_FALSE(machine.robot().located());
  CHECK_FALSE(machine.robot().quietReadings().has_value());
}
