#pragma once
// RobotBASIC's wire protocol to a real robot (SERVO Magazine, March 2008; decisions.md):
// every command is two bytes, a code then a one-byte parameter, and the robot answers every
// command with five bytes. Both layouts are tables here, so a better-sourced layout is a table
// change.

#include <array>
#include <cstdint>

#include "robot_link.h"

namespace rb::protocol {

/// Command codes. Odd codes are the negative direction of the even code before them.
struct Codes {
  uint8_t locate = 3;
  uint8_t forward = 6, backward = 7;
  uint8_t turnRight = 12, turnLeft = 13;
  uint8_t compass = 24;
  uint8_t speed = 36;
  uint8_t lookRight = 48, lookLeft = 49;
  uint8_t gps = 66;         ///< parameter 0: x, 1: y
  uint8_t beacon = 96;      ///< parameter: the beacon colour number when it fits a byte
  uint8_t pen = 129;        ///< parameter 0 up, 1 down
  uint8_t rangeRight = 192, rangeLeft = 193;
  uint8_t status = 6;       ///< sent with parameter 0 (a move of 0) to read the sensors
};
inline constexpr Codes kCodes{};

/// The largest amount one command can carry: longer moves and turns are split.
constexpr int kMaxParameter = 255;

/// Where each field sits in the five reply bytes.
struct ReplyLayout {
  int feel = 0, bumper = 1, sense = 2, resultHigh = 3, resultLow = 4;
};
inline constexpr ReplyLayout kReply{};
constexpr int kReplySize = 5;

inline RobotReply decodeReply(const std::array<uint8_t, kReplySize>& b) {
  RobotReply r;
  r.feel = b[kReply.feel];
  r.bumper = b[kReply.bumper];
  r.sense = b[kReply.sense];
  r.result = static_cast<uint16_t>(b[kReply.resultHigh] << 8 | b[kReply.resultLow]);
  return r;
}

inline std::array<uint8_t, kReplySize> encodeReply(const RobotReply& r) {
  std::array<uint8_t, kReplySize> b{};
  b[kReply.feel] = r.feel;
  b[kReply.bumper] = r.bumper;
  b[kReply.sense] = r.sense;
  b[kReply.resultHigh] = static_cast<uint8_t>(r.result >> 8);
  b[kReply.resultLow] = static_cast<uint8_t>(r.result & 0xff);
  return b;
}

}  // namespace rb::protocol
