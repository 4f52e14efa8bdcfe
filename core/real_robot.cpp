#include "real_robot.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "protocol.h"
#include "runtime_error.h"

namespace rb {

using protocol::kCodes;

RealRobot::RealRobot(std::unique_ptr<RobotLink> link) : link_(std::move(link)) {}

RobotReply RealRobot::send(uint8_t code, uint8_t param) {
  last_ = link_->transact(code, param);
  haveReply_ = true;
  return last_;
}

namespace {
/// Splits |amount| into commands of at most 255; returns the parameters.
std::vector<uint8_t> chunks(double amount) {
  long total = std::lround(std::abs(amount));
  std::vector<uint8_t> out;
  while (total > 0) {
    long part = std::min<long>(total, protocol::kMaxParameter);
    out.push_back(static_cast<uint8_t>(part));
    total -= part;
  }
  return out;
}
uint8_t angleByte(double a) { return static_cast<uint8_t>(std::min(std::lround(std::abs(a)), 255L)); }
}  // namespace

void RealRobot::locate(double x, double y, double heading) {
  send(kCodes.locate, 0);
  pose_.pos = {x, y};
  pose_.heading = normalizeDegrees(heading);
}

void RealRobot::forward(double distance) {
  uint8_t code = distance >= 0 ? kCodes.forward : kCodes.backward;
  for (uint8_t part : chunks(distance)) {
    send(code, part);
    pose_.pos += headingVector(pose_.heading) * (distance >= 0 ? part : -part);
  }
}

void RealRobot::turn(double degrees) {
  uint8_t code = degrees >= 0 ? kCodes.turnRight : kCodes.turnLeft;
  for (uint8_t part : chunks(degrees)) {
    send(code, part);
    pose_.heading = normalizeDegrees(pose_.heading + (degrees >= 0 ? part : -part));
  }
}

void RealRobot::speed(double delay) {
  send(kCodes.speed, static_cast<uint8_t>(std::clamp(std::lround(delay), 0L, 255L)));
}

void RealRobot::pen(bool down) {
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
  return send(a >= 0 ? kCodes.rangeRight : kCodes.rangeLeft, angleByte(a)).result;
}

Colour RealRobot::look(double a) {
  return send(a >= 0 ? kCodes.lookRight : kCodes.lookLeft, angleByte(a)).result;
}

double RealRobot::beacon(Colour colour) {
  return send(kCodes.beacon, colour <= 255 ? static_cast<uint8_t>(colour) : 0).result;
}

int RealRobot::compass() { return send(kCodes.compass, 0).result % 360; }
int RealRobot::gpsX() { return send(kCodes.gps, 0).result; }
int RealRobot::gpsY() { return send(kCodes.gps, 1).result; }

double RealRobot::chargeLevel() {
  throw RuntimeError("rChargeLevel(): the real robot's protocol has no battery command");
}

int64_t RealRobot::command(int64_t code, int64_t param) {
  if (code < 0 || code > 255 || param < 0 || param > 255)
    throw RuntimeError("rCommand: the code and the parameter must each be 0..255");
  return send(static_cast<uint8_t>(code), static_cast<uint8_t>(param)).result;
}

}  // namespace rb
