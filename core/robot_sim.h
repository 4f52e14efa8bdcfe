#pragma once
// The simulated robot: a disc on the canvas that moves pixel by pixel, crashes into
// obstacles, and reads its sensors from the canvas's pixels. Geometry constants live in
// sim_constants.h; docs/robot.md describes the model.

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "canvas.h"
#include "obstacle_field.h"
#include "rng.h"

namespace rb {

/// Position (pixels, y down) and heading (degrees, 0 = up, clockwise positive).
struct Pose {
  Eigen::Vector2d pos{0, 0};
  double heading = 0;
};

class SimRobot {
 public:
  SimRobot(Canvas& canvas, Rng& rng);

  bool located() const { return located_; }
  const Pose& pose() const { return pose_; }
  double radius() const { return radius_; }
  Colour colour() const { return colour_; }
  bool penDown() const { return penDown_; }
  double slipPercent() const { return slip_; }

  /// rLocate. Throws RuntimeError when the robot would overlap an obstacle.
  void locate(double x, double y, double heading, double radius, Colour colour);
  /// rForward: moves in steps of at most one pixel, calling `onStep` after each. On a crash the
  /// robot stays where it last was free and RuntimeError("robot crashed into an obstacle") is
  /// thrown. Returns the distance actually asked for after slip.
  double forward(double distance, const std::function<void()>& onStep);
  /// rTurn: turns in steps of at most one degree (a disc cannot crash by turning).
  double turn(double degrees, const std::function<void()>& onStep);
  void setPen(bool down);
  void setSlip(double percent) { slip_ = percent; }

  // Sensors (see sim_constants.h for the geometry).
  int bumper();
  int feel();
  int sense();
  double range(double relativeAngle);
  Colour look(double relativeAngle);
  double beacon(Colour colour);
  int compass() const;
  int gpsX() const;
  int gpsY() const;
  double chargeLevel() const;

  /// True when the disc at `pos` overlaps an obstacle pixel.
  bool collides(const Eigen::Vector2d& pos);

 private:
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
  /// Pixels around the centre out to `reach`, sorted by bearing (cached per reach).
  const std::vector<Offset>& offsetsWithin(double reach);
  RayHit castRay(double absoluteAngle);
  double applySlip(double amount);
  void extendTrail();

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
  double cachedReach_ = -1;
  std::vector<Offset> offsets_;
};

/// Degrees normalised to [0, 360).
double normalizeDegrees(double d);
/// The unit vector of a heading (0 = up, clockwise; y grows downward).
Eigen::Vector2d headingVector(double degrees);

}  // namespace rb
