#include "robot/robot.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace rb {

double normalizeDegrees(double d) {
  double r = std::fmod(d, 360.0);
  if (r < 0) r += 360.0;
  if (r >= 360.0) r = 0;
  return r;
}

Eigen::Vector2d headingVector(double degrees) {
  // Heading 0 points up (-y); the rotation is clockwise on screen, where y grows downward.
  return Eigen::Rotation2Dd(degrees * std::numbers::pi / 180.0) * Eigen::Vector2d(0, -1);
}

}  // namespace rb
