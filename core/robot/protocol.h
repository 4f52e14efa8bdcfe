#pragma once
// RobotBASIC's wire protocol to a real robot (SERVO Magazine, March 2008; decisions.md):
// every command is two bytes, a code then a one-byte parameter, and the robot answers every
// command with five bytes. Both layouts are tables here, so a better-sourced layout is a table
// change. docs/real-robot.md prints the same tables for users.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "robot/robot_link.h"

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

/// The largest move or turn one statement may ask of a real robot (it becomes up to 129
/// commands); anything beyond is surely a mistake and would keep the robot busy for minutes.
constexpr double kMaxAmount = 32767;

/// Where each field sits in the five reply bytes, and which bits a well-formed reply may set.
/// The order bumper, feel, sense is inferred (decisions.md, 2026-11-26): the "SR15 RROS for
/// Arduino" sketch, a robot firmware written for RobotBASIC's protocol, answers every command
/// with rBumper, rFeel, rSense, 0, 0, with the same bit layouts as rb.
/// rBumper has four bumpers and rFeel five sensors; rSense is left open because a robot may
/// report any "sense" data there (SERVO, March 2008).
struct ReplyLayout {
  int bumper = 0, feel = 1, sense = 2, resultHigh = 3, resultLow = 4;
  uint8_t bumperMask = 0x0f, feelMask = 0x1f, senseMask = 0xff;
};
inline constexpr ReplyLayout kReply{};
constexpr int kReplySize = 5;

/// The name of the RobotBASIC statement a command code belongs to ("rForward"), or "" for a
/// code outside the table (a user-defined rCommand).
constexpr std::string_view commandName(uint8_t code) {
  switch (code) {
    case kCodes.locate: return "rLocate";
    case kCodes.forward: return "rForward";
    case kCodes.backward: return "rForward (backward)";
    case kCodes.turnRight: return "rTurn (right)";
    case kCodes.turnLeft: return "rTurn (left)";
    case kCodes.compass: return "rCompass";
    case kCodes.speed: return "rSpeed";
    case kCodes.lookRight: return "rLook (right)";
    case kCodes.lookLeft: return "rLook (left)";
    case kCodes.gps: return "rGPS";
    case kCodes.beacon: return "rBeacon";
    case kCodes.pen: return "rPen";
    case kCodes.rangeRight: return "rRange (right)";
    case kCodes.rangeLeft: return "rRange (left)";
    default: return "";
  }
}

/// Bytes as lower-case hex pairs separated by spaces ("06 ff"), for messages and logs.
/// The bytes in hex ("06 ff 5a"), at most `shown` of them, then " ..." when there were more.
inline std::string hexBytes(const uint8_t* data, size_t n, size_t shown = SIZE_MAX) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string s;
  for (size_t i = 0; i < n && i < shown; ++i) {
    if (i) s += ' ';
    s += kDigits[data[i] >> 4];
    s += kDigits[data[i] & 0xf];
  }
  if (n > shown) s += " ...";
  return s;
}

/// True when every field of a reply only sets bits its sensors can set: a reply that does not
/// is noise on the line or a robot speaking another protocol.
inline bool plausibleReply(const std::array<uint8_t, kReplySize>& b) {
  return (b[kReply.bumper] & ~kReply.bumperMask) == 0 && (b[kReply.feel] & ~kReply.feelMask) == 0 &&
         (b[kReply.sense] & ~kReply.senseMask) == 0;
}

inline RobotReply decodeReply(const std::array<uint8_t, kReplySize>& b) {
  RobotReply r;
  r.bumper = b[kReply.bumper];
  r.feel = b[kReply.feel];
  r.sense = b[kReply.sense];
  r.result = static_cast<uint16_t>(b[kReply.resultHigh] << 8 | b[kReply.resultLow]);
  return r;
}

inline std::array<uint8_t, kReplySize> encodeReply(const RobotReply& r) {
  std::array<uint8_t, kReplySize> b{};
  b[kReply.bumper] = r.bumper;
  b[kReply.feel] = r.feel;
  b[kReply.sense] = r.sense;
  b[kReply.resultHigh] = static_cast<uint8_t>(r.result >> 8);
  b[kReply.resultLow] = static_cast<uint8_t>(r.result & 0xff);
  return b;
}

}  // namespace rb::protocol
