#pragma once
// The transport to a real robot: something that sends one two-byte command and returns the
// robot's reply. drivers/ implements it over a serial port; tests implement it in memory.

#include <cstdint>
#include <functional>
#include <string>

namespace rb {

/// The robot's answer to every command, decoded (byte layout: protocol.h, decisions.md).
struct RobotReply {
  uint8_t feel = 0;     ///< rFeel() bits
  uint8_t bumper = 0;   ///< rBumper() bits
  uint8_t sense = 0;    ///< rSense() bits
  uint16_t result = 0;  ///< the command's 16-bit result
};

/// One connection to a robot; destroying it closes the port.
class RobotLink {
 public:
  virtual ~RobotLink() = default;
  /// Sends command `code` with parameter `param` and waits for the reply. Any fault (no answer
  /// in time, a short or malformed reply, the device gone) throws RuntimeError with a message
  /// naming the port.
  virtual RobotReply transact(uint8_t code, uint8_t param) = 0;
  /// The port, for messages ("/dev/rfcomm0").
  virtual std::string name() const = 0;
  /// Called at least every 50 ms while transact() waits for the robot (a slow robot, a long
  /// --robot-timeout): the run's limits end the wait by throwing from it.
  virtual void setWhileWaiting(std::function<void()> hook) { (void)hook; }
};

}  // namespace rb
