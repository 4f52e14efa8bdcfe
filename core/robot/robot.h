#pragma once
// The robot a program's robot statements drive: the simulator (robot_sim.h) or a real robot at
// the end of a serial link (real_robot.h). Machine::robot() returns whichever is active, so the
// built-ins, traces, pictures and live views ask one object and never choose between the two.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>

#include "screen/canvas.h"

namespace rb {

/// Position (pixels, y down) and heading (degrees, 0 = up, clockwise positive).
struct Pose {
  Eigen::Vector2d pos{0, 0};
  double heading = 0;
};

/// Degrees normalised to [0, 360).
double normalizeDegrees(double d);
/// The unit vector of a heading (0 = up, clockwise; y grows downward).
Eigen::Vector2d headingVector(double degrees);

/// Called after each pixel or degree of a motion a live view animates (empty: move at once).
using StepFn = std::function<void()>;

/// Bumper and infrared readings a live view shows, got without sending or moving anything.
struct QuietReadings {
  int bumper = 0;
  int feel = 0;
};

class Robot {
 public:
  virtual ~Robot() = default;

  // What it is and where: for pictures, traces and live views. Reading these sends nothing.
  /// Whether rLocate placed it (until then a picture shows no robot).
  virtual bool located() const = 0;
  /// The pose: the simulator's own, or a real robot's dead-reckoned one.
  virtual const Pose& pose() const = 0;
  virtual bool penDown() const = 0;
  /// rLocate's radius and colour, for drawing it.
  virtual double radius() const = 0;
  virtual Colour colour() const = 0;
  /// The latest bumper and infrared readings, or nothing when there are none to show (not
  /// placed yet; a real robot that has not replied yet).
  virtual std::optional<QuietReadings> quietReadings() = 0;

  // The robot statements. Errors (a crash, a silent robot) are RuntimeErrors.
  virtual void locate(double x, double y, double heading, double radius, Colour colour) = 0;
  /// Returns the distance actually moved (after slip). `onStep` animates, when given.
  virtual double forward(double distance, const StepFn& onStep) = 0;
  virtual double turn(double degrees, const StepFn& onStep) = 0;
  virtual void setPen(bool down) = 0;
  /// rSpeed's delay (ms per pixel or degree). The run paces simulated motion itself.
  virtual void setSpeed(double delay) = 0;

  // Sensors.
  virtual int bumper() = 0;
  virtual int feel() = 0;
  virtual int sense() = 0;
  /// Angles are relative to the heading, degrees.
  virtual double range(double relativeAngle) = 0;
  virtual Colour look(double relativeAngle) = 0;
  virtual double beacon(Colour colour) = 0;
  virtual int compass() = 0;
  virtual int gpsX() = 0;
  virtual int gpsY() = 0;
  virtual double chargeLevel() = 0;
  /// rCommand: a raw protocol command; its 16-bit result.
  virtual int64_t command(int64_t code, int64_t param) = 0;
};

}  // namespace rb
