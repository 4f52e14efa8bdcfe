#pragma once
// The RobotLink of a real robot on a serial port: each command is two bytes out and five
// bytes back within a timeout. Every fault becomes a RuntimeError that names the port; the
// interpreter adds the program line.

#include <string>

#include "robot/robot_link.h"
#include "serial_port.h"

namespace rb::drivers {

/// How to talk to the robot (from rb run's options).
struct SerialLinkOptions {
  int baud = 9600;              ///< --baud
  double timeoutSeconds = 2;    ///< --robot-timeout: for the whole reply to each command
};

/// A robot on a serial port: one SerialPort, one command at a time.
class SerialLink : public RobotLink {
 public:
  /// Opens the port (see SerialPort for the errors).
  SerialLink(std::string path, const SerialLinkOptions& options);

  /// Flushes stale input, sends the command and reads the reply. Throws RuntimeError when the
  /// robot does not answer in time, answers short, answers with bytes no robot sends, or the
  /// device goes away; the port is closed then, and every later command fails at once.
  RobotReply transact(uint8_t code, uint8_t param) override;
  std::string name() const override { return port_.path(); }
  void setWhileWaiting(std::function<void()> hook) override { port_.whileWaiting = std::move(hook); }

 private:
  [[noreturn]] void fault(const std::string& message);

  SerialPort port_;
  double timeoutSeconds_;
};

}  // namespace rb::drivers
