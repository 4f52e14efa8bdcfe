#pragma once
// The simulated robot: a disc on the canvas that moves pixel by pixel, crashes when the part of
// its rim that leads the motion touches an obstacle, and reads its sensors from the canvas's
// pixels. Geometry constants live in sim_constants.h; docs/robot.md describes the model.

#include <Eigen/Core>
#include <vector>

#include "base/rng.h"
#include "robot/obstacle_field.h"
#include "robot/robot.h"
#include "screen/canvas.h"

namespace rb {

class SimRobot final : public Robot {
 public:
  SimRobot(Canvas& canvas, Rng& rng);

  bool located() const override { return located_; }
  const Pose& pose() const override { return pose_; }
  double radius() const override { return radius_; }
  Colour colour() const override { return colour_; }
  bool penDown() const override { return penDown_; }
  /// Its bumper and infrared sensors, read now (reading moves nothing and draws no number).
  std::optional<QuietReadings> quietReadings() override;
  double slipPercent() const { return slip_; }

  /// rLocate. A robot that would stick out of the screen is moved just inside, touching the
  /// edge. Throws RuntimeError when the robot would then overlap a drawn obstacle.
  void locate(double x, double y, double heading, double radius, Colour colour) override;
  /// rForward: moves in steps of at most one pixel. A step crashes when the quadrant of the rim
  /// that leads the motion (the front one going forward, the rear one backing up) sweeps over an
  /// obstacle pixel: the robot stays where it last was and RuntimeError("robot crashed into an
  /// obstacle") is thrown. `onStep`, when given, is called after each step (a live view animates
  /// the move; without it the pen draws the whole segment at once). Returns the distance after
  /// slip.
  double forward(double distance, const StepFn& onStep) override;
  /// rTurn: with `onStep` it turns in steps of one degree, calling it after each; turning in
  /// place never crashes (a turning disc covers nothing new).
  double turn(double degrees, const StepFn& onStep) override;
  void setPen(bool down) override;
  /// Nothing to do: the run paces simulated motion (Machine::robotStepped).
  void setSpeed(double) override {}
  void setSlip(double percent) { slip_ = percent; }

  // Sensors (see sim_constants.h for the geometry).
  int bumper() override;
  int feel() override;
  int sense() override;
  double range(double relativeAngle) override;
  Colour look(double relativeAngle) override;
  double beacon(Colour colour) override;
  int compass() override;
  int gpsX() override;
  int gpsY() override;
  double chargeLevel() override;
  /// A raw command means nothing to the simulator: 0.
  int64_t command(int64_t, int64_t) override { return 0; }

  /// True when the disc at `pos` overlaps an obstacle pixel (rLocate's test).
  bool collides(const Eigen::Vector2d& pos);
  /// True when a step from `from` to `to` (at most kMaxStep long, in the unit direction `dir`)
  /// crashes: an obstacle pixel outside the disc at `from` is inside the disc at `to`, in the
  /// quadrant around `dir` (seen from `to`, both edges included).
  bool stepCrashes(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Eigen::Vector2d& dir);
  /// The runtime error of a crash into the pixel stepCrashes hit: what it was and the usual fix.
  std::string crashMessage() const;

 private:
  int hitX_ = 0, hitY_ = 0;  ///< the obstacle pixel of the last crash
  /// A pixel near the robot, relative to its centre pixel.
  struct Offset {
    int dx, dy;
    float dist;     ///< from the centre pixel
    float bearing;  ///< degrees, 0 = up, clockwise, in [0, 360)
  };
  struct RayHit {
    double distance;  ///< from the centre
    Colour colour;
    bool edge;        ///< the ray left the screen
  };

  void requireLocated() const;
  Eigen::Vector2i centrePixel() const;
  /// Rebuilds the offset tables when the radius changed.
  void prepareOffsets();
  RayHit castRay(double absoluteAngle);
  double applySlip(double amount);
  void extendTrail();
  Colour trailColour() const;

  Canvas& canvas_;
  Rng& rng_;
  ObstacleField field_;
  Pose pose_;
  double radius_ = 20;
  Colour colour_ = 1;
  bool located_ = false;
  bool penDown_ = false;
  double slip_ = 0;
  double travelled_ = 0;
  double turned_ = 0;
  // Every pixel within the farthest sensor's reach, sorted by distance, and the same pixels
  // bucketed by whole degrees of bearing (each bucket sorted by distance). With the distance
  // to the nearest obstacle known, a sensor visits only pixels at least that far away.
  double offsetsRadius_ = -1;
  double offsetsReach_ = 0;
  std::vector<Offset> byDistance_;
  std::vector<Offset> byBearing_[360];
  /// distanceStart_[k]: the first index in byDistance_ at distance >= k; bearingStart_[b][k] the
  /// same in bucket b. They replace binary searches in the sensors' inner loops.
  std::vector<uint32_t> distanceStart_;
  std::vector<uint16_t> bearingStart_[360];
  /// The pixels a step can sweep the rim over (from r - kMaxStep - rounding to r + rounding),
  /// sorted by bearing; rimStart_[b] is the first at bearing >= b degrees. rimSlack_ (degrees)
  /// bounds how much a bearing seen from the centre pixel differs from one seen from the
  /// exact centre, for those pixels.
  std::vector<Offset> rim_;
  std::vector<uint32_t> rimStart_;
  double rimSlack_ = 0;
  /// Where the pen's trail ends (the robot's centre when it last drew).
  Eigen::Vector2d penAt_{0, 0};
};

}  // namespace rb
