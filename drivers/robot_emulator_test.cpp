// The robot emulator without a port: what it answers to each command and when it misbehaves
// on purpose.
#include <catch2/catch.hpp>

#include "robot/protocol.h"
#include "robot_emulator.h"

using namespace rb;
using namespace rb::drivers;

namespace {

RobotReply decode(const EmulatorAnswer& a) {
  REQUIRE(a.bytes.size() == 5);
  std::array<uint8_t, 5> b{};
  std::copy(a.bytes.begin(), a.bytes.end(), b.begin());
  return protocol::decodeReply(b);
}

}  // namespace

TEST_CASE("the emulated robot starts at the centre, moves, turns and reports its position", "[emulator]") {
  RobotEmulator emu({});
  CHECK(decode(emu.handle(66, 0)).result == 400);
  CHECK(decode(emu.handle(66, 1)).result == 300);
  emu.handle(6, 120);
  CHECK(decode(emu.handle(66, 1)).result == 180);
  emu.handle(12, 90);
  CHECK(decode(emu.handle(24, 0)).result == 90);
  emu.handle(7, 100);  // backward
  CHECK(decode(emu.handle(66, 0)).result == 300);
  emu.handle(13, 180);
  CHECK(decode(emu.handle(24, 0)).result == 270);
  emu.handle(3, 0);  // rLocate: back to the start
  CHECK(emu.robot().pose().pos.x() == 400);
  CHECK(emu.robot().pose().pos.y() == 300);
  CHECK(emu.robot().pose().heading == 0);
  CHECK(emu.commands() == 11);
}

TEST_CASE("the emulated robot's sensors see the screen edge", "[emulator]") {
  RobotEmulator emu({});
  // Range from the edge of the disc (radius 20) to the screen edge, ahead and to the left.
  CHECK(decode(emu.handle(192, 0)).result == Approx(280).margin(2));
  CHECK(decode(emu.handle(193, 90)).result == Approx(380).margin(2));
  // Driving into the top wall stops the robot there with its front bumper pressed; the
  // emulator keeps answering.
  emu.handle(6, 255);
  RobotReply r = decode(emu.handle(6, 255));
  CHECK(r.bumper & 4);
  CHECK(r.feel & 4);
  CHECK(emu.robot().pose().pos.y() < 30);
  CHECK(emu.robot().pose().pos.y() >= 20);
  // Code outside the table: the sensors and a result of 0.
  CHECK(decode(emu.handle(200, 7)).result == 0);
}

TEST_CASE("the emulator answers bumper, feel, sense, then the result high byte first", "[emulator]") {
  // Read the bytes themselves, not through protocol::decodeReply: the order on the wire is
  // what a real robot's firmware (the SR15 RROS sketch) sends.
  RobotEmulator emu({});
  CHECK(emu.handle(66, 0).bytes == std::vector<uint8_t>{0, 0, 0, 0x01, 0x90});  // x = 400
  // Up against the top wall: the front bumper (4) in the first byte; the infrared sensors
  // that see the wall (front and both 45-degree ones: 2 + 4 + 8) in the second.
  emu.handle(6, 255);
  CHECK(emu.handle(6, 255).bytes == std::vector<uint8_t>{4, 14, 0, 0, 0});
}

TEST_CASE("the pen draws without making the trail an obstacle", "[emulator]") {
  RobotEmulator emu({});
  emu.handle(129, 1);
  emu.handle(6, 100);
  emu.handle(12, 180);
  RobotReply r = decode(emu.handle(6, 100));  // back over its own trail
  CHECK(r.bumper == 0);
  CHECK(emu.robot().pose().pos.y() == Approx(300));
}

TEST_CASE("faults on purpose: dropped, garbled and short answers, dying", "[emulator]") {
  EmulatorOptions o;
  o.dropEvery = 3;
  o.garbleEvery = 4;
  o.shortEvery = 5;
  o.dieAfter = 6;
  RobotEmulator emu(o);
  CHECK(emu.handle(6, 0).bytes.size() == 5);
  CHECK(emu.handle(6, 0).bytes.size() == 5);
  EmulatorAnswer dropped = emu.handle(6, 0);
  CHECK(dropped.bytes.empty());
  CHECK(dropped.note == "dropped");
  EmulatorAnswer garbled = emu.handle(6, 0);
  CHECK(garbled.bytes == std::vector<uint8_t>(7, 0xff));
  EmulatorAnswer shortAnswer = emu.handle(6, 0);
  CHECK(shortAnswer.bytes.size() == 2);
  CHECK_FALSE(shortAnswer.die);
  EmulatorAnswer last = emu.handle(6, 0);
  CHECK(last.bytes.empty());  // the 6th is dropped (every 3rd), and then the port closes
  CHECK(last.die);
}

TEST_CASE("slip makes moves inexact, repeatably for a seed", "[emulator]") {
  EmulatorOptions o;
  o.slipPercent = 20;
  o.seed = 7;
  RobotEmulator a(o), b(o);
  a.handle(6, 100);
  b.handle(6, 100);
  CHECK(a.robot().pose().pos.y() == b.robot().pose().pos.y());
  CHECK(a.robot().pose().pos.y() != Approx(200));
}
