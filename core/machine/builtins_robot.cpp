// Robot built-ins: rLocate, rForward, rTurn, the sensors. They act on the active robot
// (Machine::robot(): the simulator or a connected real robot) and report what they did to the
// Machine's observer for `rb trace`.
#include <cmath>
#include <functional>

#include "machine/builtins_impl.h"
#include "base/runtime_error.h"
#include "robot/sim_constants.h"

namespace rb::builtins {

namespace {

using K = BuiltinKind;

std::string argText(Args& a) {
  std::string s;
  for (int i = 0; i < a.size(); ++i) {
    if (i) s += ',';
    s += formatValue(a[i]);
  }
  return s;
}

/// Tells the observer (rb trace, a live view) what the built-in did; formats its arguments only
/// when someone is listening.
void report(Machine& m, RobotEvent::Kind kind, Args& a, std::optional<double> value = std::nullopt) {
  if (m.observed()) m.emit(kind, a.builtin().name, argText(a), value);
}

/// The largest distance (pixels) or coordinate a robot command takes: the screen is 800x600,
/// so this leaves room for any real program and keeps every count of steps an int.
constexpr double kMaxDistance = 1e6;
/// The largest angle (degrees) a robot command takes; a turn steps once per degree.
constexpr double kMaxDegrees = 1e6;

/// Every sensor reads a whole number.
Value sensor(Machine& m, Args& a, double v) {
  m.noteReading(a.builtin().name, v);
  report(m, RobotEvent::Sensor, a, v);
  return Value::integer(static_cast<int64_t>(v));
}

Value rLocate(Machine& m, Args& a) {
  double x = a.within(0, kMaxDistance), y = a.within(1, kMaxDistance);
  double heading = a.has(2) ? a.within(2, kMaxDegrees) : 0;
  double radius = a.numOr(3, sim::kDefaultRadius);
  Colour colour = a.has(4) ? a.colour(4) : static_cast<Colour>(sim::kDefaultColour);
  m.robot().locate(x, y, heading, radius, colour);
  report(m, RobotEvent::Locate, a);
  return {};
}

/// The per-step callback of a move: only when rSpeed paces it or a live view shows it (it then
/// animates each step); otherwise a move is instantaneous.
std::function<void()> stepper(Machine& m) {
  if (!m.animatesRobot()) return nullptr;
  return [&m] { m.robotStepped(); };
}

Value rForward(Machine& m, Args& a) {
  try {
    double distance = a.within(0, kMaxDistance);
    m.robot().forward(distance, stepper(m));
  } catch (const RuntimeError& e) {
    // A collision is a crash; an unplaced robot or a bad distance is only an error.
    if (std::string_view(e.code()) == "rb-robot-crash") report(m, RobotEvent::Crash, a);
    throw;
  }
  report(m, RobotEvent::Move, a);
  return {};
}

Value rTurn(Machine& m, Args& a) {
  double degrees = a.within(0, kMaxDegrees);
  m.robot().turn(degrees, stepper(m));
  report(m, RobotEvent::Turn, a);
  return {};
}

Value rSpeed(Machine& m, Args& a) {
  double s = a.within(0, kMaxDistance);
  if (s < 0) throw RuntimeError(a.describe(0) + " must not be negative");
  m.robotSpeed = s;
  m.robot().setSpeed(s);
  report(m, RobotEvent::Setting, a);
  return {};
}

Value rPen(Machine& m, Args& a) {
  m.robot().setPen(a.num(0) != 0);
  report(m, RobotEvent::Pen, a);
  return {};
}

Value rInvisible(Machine& m, Args& a) {
  std::vector<Colour> list;
  for (int i = 0; i < a.size(); ++i) list.push_back(a.colour(i));
  m.canvas().setInvisible(std::move(list));
  report(m, RobotEvent::Setting, a);
  return {};
}

Value rSlip(Machine& m, Args& a) {
  double p = a.num(0);
  if (p < 0 || p > 100) throw RuntimeError(a.describe(0) + " must be a percentage from 0 to 100");
  m.simulator().setSlip(p);  // the simulator's error; a real robot has its own
  report(m, RobotEvent::Setting, a);
  return {};
}

Value rCommPort(Machine& m, Args& a) {
  m.useCommPort(a.integer(0));
  report(m, RobotEvent::Setting, a);
  return {};
}

Value rCommand(Machine& m, Args& a) {
  int64_t code = a.integer(0), param = a.integer(1);
  return sensor(m, a, static_cast<double>(m.robot().command(code, param)));  // 0 in the simulator
}

#define RB_SENSOR(name, expr) \
  Value name(Machine& m, Args& a) { return sensor(m, a, static_cast<double>(m.robot().expr)); }
RB_SENSOR(rBumper, bumper())
RB_SENSOR(rFeel, feel())
RB_SENSOR(rSense, sense())
RB_SENSOR(rRange, range(a.has(0) ? a.within(0, kMaxDegrees) : 0))
RB_SENSOR(rLook, look(a.has(0) ? a.within(0, kMaxDegrees) : 0))
RB_SENSOR(rBeacon, beacon(a.colour(0)))
RB_SENSOR(rCompass, compass())
RB_SENSOR(rGPSX, gpsX())
RB_SENSOR(rGPSY, gpsY())
#undef RB_SENSOR

Value rChargeLevel(Machine& m, Args& a) {
  return sensor(m, a, std::floor(m.robot().chargeLevel()));
}

}  // namespace

void appendRobotBuiltins(std::vector<Builtin>& t) {
  t.insert(t.end(), {
      {"rLocate", K::Command, "robot", "x, y [, heading [, radius [, colour]]]", rLocate, 0,
       "places the robot's centre at (x, y), heading 0 = up (radius 20, colour Blue by default)",
       trait::kPlacesRobot},
      {"rForward", K::Command, "robot", "distance", rForward, 0,
       "moves the robot forward (negative: backward), pixel by pixel; a crash stops the program",
       trait::kNeedsRobot},
      {"rTurn", K::Command, "robot", "degrees", rTurn, 0, "turns the robot (positive: clockwise)",
       trait::kNeedsRobot},
      {"rSpeed", K::Command, "robot", "delay", rSpeed, 0,
       "milliseconds per pixel or degree of motion (bigger is slower)"},
      {"rPen", K::Command, "robot", "state", rPen, 0,
       "Down (or non-zero) draws the robot's path, Up (0) stops"},
      {"rInvisible", K::Command, "robot", "[colour...]", rInvisible, 0,
       "colours the robot ignores (replaces the list); the pen draws in the first"},
      {"rSlip", K::Command, "robot", "percent", rSlip, 0,
       "random error of up to percent in every move and turn (seeded by --seed)"},
      {"rCommPort", K::Command, "robot", "port", rCommPort, 0,
       "0: use the simulator; n: drive a real robot on serial port n", trait::kRealRobot},
      {"rCommand", K::Function, "robot", "code, parameter", rCommand, 0,
       "sends a raw command to a real robot and returns its 16-bit result (0 in the simulator)"},
      {"rBumper", K::Function, "robot", "", rBumper, 0,
       "bumpers touching something: 1 rear, 2 right, 4 front, 8 left", trait::kNeedsRobot},
      {"rFeel", K::Function, "robot", "", rFeel, 0,
       "infrared sensors seeing something within 20 pixels: 1 right, 2 front-right, 4 front, "
       "8 front-left, 16 left", trait::kNeedsRobot},
      {"rSense", K::Function, "robot", "", rSense, 0,
       "floor line sensors over a drawn line: 4 left, 2 middle, 1 right", trait::kNeedsRobot},
      {"rRange", K::Function, "robot", "[angle]", rRange, 0,
       "pixels from the robot's edge to the first obstacle in the direction heading + angle",
       trait::kNeedsRobot},
      {"rLook", K::Function, "robot", "[angle]", rLook, 0,
       "colour of the first obstacle in the direction heading + angle (0 at the screen edge)",
       trait::kNeedsRobot},
      {"rBeacon", K::Function, "robot", "colour", rBeacon, 0,
       "distance to a beacon of that colour straight ahead if nothing hides it, else 0",
       trait::kNeedsRobot},
      {"rCompass", K::Function, "robot", "", rCompass, 0, "the robot's heading, 0..359 degrees",
       trait::kNeedsRobot},
      {"rGPSX", K::Function, "robot", "", rGPSX, 0, "x of the robot's centre", trait::kNeedsRobot},
      {"rGPSY", K::Function, "robot", "", rGPSY, 0, "y of the robot's centre", trait::kNeedsRobot},
      {"rChargeLevel", K::Function, "robot", "", rChargeLevel, 0,
       "battery charge in percent: 100 at the start, 1 less per 1000 pixels driven"},
  });
}

}  // namespace rb::builtins
