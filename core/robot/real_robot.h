#pragma once
// A real robot driven through a RobotLink with RobotBASIC's wire protocol: each robot command
// of a program becomes one or more two-byte commands, and sensor functions read the robot's
// replies. The robot's pose is dead-reckoned from the commands sent, so traces and live views
// can show where it should be. No serial port here: drivers/ opens one and hands over a link.

#include <functional>
#include <memory>
#include <string>

#include "robot/robot.h"
#include "robot/robot_link.h"
#include "robot/sim_constants.h"
#include "screen/canvas.h"

namespace rb {

/// Where a real robot is assumed to start, and where the protocol's rLocate command (which
/// carries no coordinates) puts the emulated robot: the screen centre facing up, the start of
/// the seed document's programs. The robot emulator uses the same numbers.
constexpr double kRealStartX = 400;
constexpr double kRealStartY = 300;
constexpr double kRealStartHeading = 0;

/// The robot statements of a program, carried out by a robot at the other end of a link.
class RealRobot final : public Robot {
 public:
  /// Takes over the link; destroying the RealRobot closes it (rCommPort 0, errors, exit).
  explicit RealRobot(std::unique_ptr<RobotLink> link);
  /// Called between the commands of one long move or turn (each waits for the robot's answer):
  /// the run's limits end a statement that would otherwise wait command after command.
  std::function<void()> betweenCommands;

  /// The port, for messages.
  std::string name() const { return link_->name(); }
  /// The dead-reckoned pose.
  const Pose& pose() const override { return pose_; }
  /// Whether rLocate placed it (until then a picture shows no robot, as for the simulator).
  bool located() const override { return located_; }
  /// Whether the last rPen sent put the pen down.
  bool penDown() const override { return penDown_; }
  /// rLocate's radius and colour: the protocol carries neither, but pictures draw them.
  double radius() const override { return radius_; }
  Colour colour() const override { return colour_; }
  /// What the robot's last reply said (no command is sent for it); nothing before the first.
  std::optional<QuietReadings> quietReadings() override;

  /// What the link did so far, for a live view (reading it sends nothing).
  struct LinkStats {
    uint64_t commands = 0;  ///< commands sent
    uint64_t replies = 0;   ///< replies received
    uint8_t lastCode = 0, lastParam = 0;  ///< the last command sent
    RobotReply last;        ///< the last reply (valid when replies > 0)
    std::string fault;      ///< the link's fault, when one stopped it
  };
  const LinkStats& linkStats() const { return stats_; }

  /// rLocate: sends the initialise command; the dead-reckoned pose becomes (x, y, heading).
  void locate(double x, double y, double heading, double radius, Colour colour) override;
  /// rForward: one command per 255 pixels (backward for a negative distance); 0 sends one
  /// move of 0, which refreshes the sensors. The robot moves on its own: `onStep` is not called.
  double forward(double distance, const StepFn& onStep) override;
  /// rTurn: one command per 255 degrees, right for positive, left for negative.
  double turn(double degrees, const StepFn& onStep) override;
  /// rSpeed: the delay, clamped to a byte.
  void setSpeed(double delay) override;
  /// rPen: 1 down, 0 up.
  void setPen(bool down) override;
  /// rBumper(), rFeel(), rSense(): from the latest reply (a status command first if none yet).
  int bumper() override;
  int feel() override;
  int sense() override;
  /// rRange(a) and rLook(a): the angle relative to the heading, normalised to -180..180; the
  /// sign picks the right or left command.
  double range(double relativeAngle) override;
  Colour look(double relativeAngle) override;
  /// rBeacon(c): the colour travels as the parameter when it fits a byte.
  double beacon(Colour colour) override;
  int compass() override;
  int gpsX() override;
  int gpsY() override;
  /// rChargeLevel(): the protocol has no battery command, so this is a runtime error.
  double chargeLevel() override;
  /// rCommand: a raw command; returns the reply's 16-bit result.
  int64_t command(int64_t code, int64_t param) override;

 private:
  RobotReply send(uint8_t code, uint8_t param);
  /// Sends `amount` (a move or a turn) as commands of at most 255; `apply` updates the pose
  /// after each command the robot acknowledged.
  template <typename Apply>
  void sendSplit(const char* what, double amount, uint8_t positiveCode, uint8_t negativeCode,
                 Apply apply);

  std::unique_ptr<RobotLink> link_;
  Pose pose_{Eigen::Vector2d(kRealStartX, kRealStartY), kRealStartHeading};
  bool located_ = false;
  bool penDown_ = false;
  double radius_ = sim::kDefaultRadius;
  Colour colour_ = static_cast<Colour>(sim::kDefaultColour);
  bool haveReply_ = false;
  RobotReply last_;
  LinkStats stats_;
};

}  // namespace rb
