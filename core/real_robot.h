#pragma once
// A real robot driven through a RobotLink with RobotBASIC's wire protocol: each robot command
// of a program becomes one or more two-byte commands, and sensor functions read the robot's
// replies. The robot's pose is dead-reckoned from the commands sent, so traces and live views
// can show where it should be.

#include <memory>
#include <string>

#include "canvas.h"
#include "robot_link.h"
#include "robot_sim.h"

namespace rb {

class RealRobot {
 public:
  explicit RealRobot(std::unique_ptr<RobotLink> link);

  std::string name() const { return link_->name(); }
  /// The dead-reckoned pose.
  const Pose& pose() const { return pose_; }
  bool penDown() const { return penDown_; }

  void locate(double x, double y, double heading);
  void forward(double distance);
  void turn(double degrees);
  void speed(double delay);
  void pen(bool down);
  int bumper();
  int feel();
  int sense();
  double range(double relativeAngle);
  Colour look(double relativeAngle);
  double beacon(Colour colour);
  int compass();
  int gpsX();
  int gpsY();
  double chargeLevel();
  /// rCommand: a raw command; returns the reply's 16-bit result.
  int64_t command(int64_t code, int64_t param);

 private:
  RobotReply send(uint8_t code, uint8_t param);

  std::unique_ptr<RobotLink> link_;
  Pose pose_;
  bool penDown_ = false;
  bool haveReply_ = false;
  RobotReply last_;
};

}  // namespace rb
