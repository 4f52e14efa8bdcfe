#include "robot/real_robot.h"

#include <algorithm>
#include <cmath>

#include "robot/protocol.h"
#include "base/number.h"
#include "base/runtime_error.h"

namespace rb {

using protocol::kCodes;

RealRobot::RealRobot(std::unique_ptr<RobotLink> link) : link_(std::move(link)) {}

RobotReply RealRobot::send(uint8_t code, uint8_t param) {
  ++stats_.commands;
  stats_.lastCode = code;
  stats_.lastParam = param;
  try {
    last_ = link_->transact(code, param);
  } catch (const RuntimeError& e) {
    stats_.fault = e.what();
    throw;
  }
  haveReply_ = true;
  ++stats_.replies;
  stats_.last = last_;
  return last_;
}

namespace {

/// An angle as a byte parameter and a direction: the relative angle is first brought into
/// -180..180, so rRange(270) looks 90 degrees to the left as on the simulator.
struct SidedAngle {
  bool left;
  uint8_t degrees;
};
SidedAngle sidedAngle(double a) {
  if (!std::isfinite(a)) throw RuntimeError("the angle is not a number");
  double r = std::remainder(a, 360.0);  // -180..180
  long d = std::lround(std::abs(r));
  return {r < 0 && d > 0, static_cast<uint8_t>(std::min(d, 180L))};
}

}  // namespace

template <typename Apply>
void RealRobot::sendSplit(const char* what, double amount, uint8_t positiveCode,
                          uint8_t negativeCode, Apply apply) {
  if (!std::isfinite(amount)) throw RuntimeError(std::string(what) + ": the amount is not a number");
  if (std::abs(amount) > protocol::kMaxAmount)
    throw RuntimeError(std::string(what) + " " + formatNumber(amount) +
                       ": too far for a real robot in one statement (at most " +
                       formatNumber(protocol::kMaxAmount) + ")");
  uint8_t code = amount >= 0 ? positiveCode : negativeCode;
  int sign = amount >= 0 ? 1 : -1;
  long total = std::lround(std::abs(amount));
  // A move of 0 is still one command: programs send it to refresh the sensors.
  do {
    long part = std::min<long>(total, protocol::kMaxParameter);
    send(code, static_cast<uint8_t>(part));
    apply(static_cast<double>(sign * part));
    total -= part;
    if (total > 0 && betweenCommands) betweenCommands();
  } while (total > 0);
}

std::optional<QuietReadings> RealRobot::quietReadings() {
  if (!haveReply_) return std::nullopt;
  return QuietReadings{last_.bumper, last_.feel};
}

void RealRobot::locate(double x, double y, double heading, double radius, Colour colour) {
  send(kCodes.locate, 0);
  located_ = true;
  radius_ = radius;
  colour_ = colour;
  pose_.pos = {x, y};
  pose_.heading = normalizeDegrees(heading);
}

double RealRobot::forward(double distance, const StepFn&) {
  sendSplit("rForward", distance, kCodes.forward, kCodes.backward,
            [this](double d) { pose_.pos += headingVector(pose_.heading) * d; });
  return distance;
}

double RealRobot::turn(double degrees, const StepFn&) {
  sendSplit("rTurn", degrees, kCodes.turnRight, kCodes.turnLeft,
            [this](double d) { pose_.heading = normalizeDegrees(pose_.heading + d); });
  return degrees;
}

void RealRobot::setSpeed(double delay) {
  send(kCodes.speed, static_cast<uint8_t>(std::clamp(std::lround(delay), 0L, 255L)));
}

void RealRobot::setPen(bool down) {
  send(kCodes.pen, down ? 1 : 0);
  penDown_ = down;
}

int RealRobot::bumper() {
  if (!haveReply_) send(kCodes.status, 0);
  return last_.bumper;
}

int RealRobot::feel() {
  if (!haveReply_) send(kCodes.status, 0);
  return last_.feel;
}

int RealRobot::sense() {
  if (!haveReply_) send(kCodes.status, 0);
  return last_.sense;
}

double RealRobot::range(double a) {
  SidedAngle s = sidedAngle(a);
  return send(s.left ? kCodes.rangeLeft : kCodes.rangeRight, s.degrees).result;
}

Colour RealRobot::look(double a) {
  SidedAngle s = sidedAngle(a);
  return send(s.left ? kCodes.lookLeft : kCodes.lookRight, s.degrees).result;
}

double RealRobot::beacon(Colour colour) {
  return send(kCodes.beacon, colour <= 255 ? static_cast<uint8_t>(colour) : 0).result;
}

int RealRobot::compass() { return send(kCodes.compass, 0).result % 360; }
int RealRobot::gpsX() { return send(kCodes.gps, 0).result; }
int RealRobot::gpsY() { return send(kCodes.gps, 1).result; }

double RealRobot::chargeLevel() {
  throw RuntimeError(
      "rChargeLevel(): the real robot's protocol has no battery command (read it with rCommand "
      "if your robot defines one)");
}

int64_t RealRobot::command(int64_t code, int64_t param) {
  if (code < 0 || code > 255 || param < 0 || param > 255)
    throw RuntimeError("rCommand(" + std::to_string(code) + ", " + std::to_string(param) +
                       "): the code and the parameter must each be 0..255");
  return send(static_cast<uint8_t>(code), static_cast<uint8_t>(param)).result;
}

}  // namespace rb
