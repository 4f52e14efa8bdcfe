#include "robot_emulator.h"

#include <algorithm>
#include <cmath>

#include "robot/protocol.h"
#include "robot/real_robot.h"
#include "base/runtime_error.h"
#include "robot/sim_constants.h"

namespace rb::drivers {

using protocol::kCodes;

namespace {

uint16_t clampResult(double v) {
  if (!std::isfinite(v) || v < 0) return 0;
  return static_cast<uint16_t>(std::min(std::lround(v), 65535L));
}

bool every(uint64_t n, uint64_t count) { return n > 0 && count % n == 0; }

}  // namespace

RobotEmulator::RobotEmulator(const EmulatorOptions& options)
    : options_(options), rng_(options.seed), robot_(canvas_, rng_) {
  // The pen draws in Green, which the robot ignores as the seed's programs do with
  // rInvisible GREEN: otherwise its own trail would be an obstacle under it.
  canvas_.setInvisible({colours::kGreen});
  robot_.locate(kRealStartX, kRealStartY, kRealStartHeading, sim::kDefaultRadius, sim::kDefaultColour);
  robot_.setSlip(options.slipPercent);
}

RobotReply RobotEmulator::execute(uint8_t code, uint8_t param) {
  RobotReply r;
  // A real robot stops at a wall and says so with its bumpers; it does not end the program.
  auto move = [&](auto&& act) {
    try {
      act();
    } catch (const RuntimeError&) {
    }
  };
  if (code == kCodes.locate) {
    robot_.locate(kRealStartX, kRealStartY, kRealStartHeading, sim::kDefaultRadius, sim::kDefaultColour);
  } else if (code == kCodes.forward || code == kCodes.backward) {
    double d = code == kCodes.forward ? param : -param;
    move([&] { robot_.forward(d, nullptr); });
  } else if (code == kCodes.turnRight || code == kCodes.turnLeft) {
    double d = code == kCodes.turnRight ? param : -param;
    move([&] { robot_.turn(d, nullptr); });
  } else if (code == kCodes.compass) {
    r.result = clampResult(robot_.compass());
  } else if (code == kCodes.lookRight || code == kCodes.lookLeft) {
    r.result = clampResult(robot_.look(code == kCodes.lookRight ? param : -param));
  } else if (code == kCodes.gps) {
    r.result = clampResult(param == 0 ? robot_.gpsX() : robot_.gpsY());
  } else if (code == kCodes.beacon) {
    r.result = clampResult(robot_.beacon(param));
  } else if (code == kCodes.pen) {
    robot_.setPen(param != 0);
  } else if (code == kCodes.rangeRight || code == kCodes.rangeLeft) {
    r.result = clampResult(robot_.range(code == kCodes.rangeRight ? param : -param));
  }
  // rSpeed and codes outside the table: nothing to do; the reply carries the sensors.
  r.feel = static_cast<uint8_t>(robot_.feel());
  r.bumper = static_cast<uint8_t>(robot_.bumper());
  r.sense = static_cast<uint8_t>(robot_.sense());
  return r;
}

EmulatorAnswer RobotEmulator::handle(uint8_t code, uint8_t param) {
  ++count_;
  EmulatorAnswer a;
  RobotReply reply = execute(code, param);
  a.die = options_.dieAfter > 0 && count_ >= options_.dieAfter;
  if (every(options_.dropEvery, count_)) {
    a.note = "dropped";
    return a;
  }
  auto bytes = protocol::encodeReply(reply);
  a.bytes.assign(bytes.begin(), bytes.end());
  if (every(options_.garbleEvery, count_)) {
    a.bytes.assign(7, 0xff);
    a.note = "garbled";
  } else if (every(options_.shortEvery, count_)) {
    a.bytes.resize(2);
    a.note = "short";
  }
  return a;
}

}  // namespace rb::drivers
