#pragma once
// The robot's image, as screenshots of RobotBASIC 4.2 show it: a circle outline about 3 pixels
// thick in the robot's colour, and a heading line of the same thickness from the centre to the
// rim. Shared by the PNG, the character view (and so the live terminal view) and, as numbers,
// the SVG, so every picture draws the same robot.

#include <algorithm>
#include <cmath>

#include "arena_view.h"
#include "robot/robot_sim.h"

namespace rb::render {

/// The thickness of the robot's outline and heading line, in screen pixels.
constexpr double kRobotStroke = 3.0;

/// The robot's image in screen coordinates, where a pixel's centre is its integer coordinate
/// (the canvas and the robot share that convention).
class RobotImage {
 public:
  /// Empty (covers nothing) unless the robot is visible with a finite pose and radius.
  explicit RobotImage(const RobotView& robot) {
    if (!robot.visible || !std::isfinite(robot.x) || !std::isfinite(robot.y) ||
        !std::isfinite(robot.radius) || robot.radius < 0)
      return;
    valid_ = true;
    cx_ = robot.x;
    cy_ = robot.y;
    r_ = robot.radius;
    const Eigen::Vector2d dir = headingVector(std::isfinite(robot.heading) ? robot.heading : 0.0);
    dx_ = dir.x();
    dy_ = dir.y();
  }

  /// The image of a robot at (cx, cy) of radius r heading along the unit vector (dx, dy), as
  /// given (a glide's pose between two recorded steps, render/animation.h).
  static RobotImage fromVector(double cx, double cy, double r, double dx, double dy) {
    RobotImage image(RobotView{});
    if (!std::isfinite(cx) || !std::isfinite(cy) || !std::isfinite(r) || r < 0 || !std::isfinite(dx) || !std::isfinite(dy))
      return image;
    image.valid_ = true;
    image.cx_ = cx;
    image.cy_ = cy;
    image.r_ = r;
    image.dx_ = dx;
    image.dy_ = dy;
    return image;
  }

  bool empty() const { return !valid_; }
  double centreX() const { return cx_; }
  double centreY() const { return cy_; }
  double radius() const { return r_; }
  /// The heading as a unit vector (0 degrees is up, angles grow clockwise).
  double headingX() const { return dx_; }
  double headingY() const { return dy_; }

  /// Whether the point (u, v) is on the image: the ring r - 3 < d <= r inside the robot's rim
  /// (3 pixels wide wherever pixel centres are sampled), or within 1.5 pixels of the segment
  /// from the centre to the rim along the heading, never outside the rim.
  bool covers(double u, double v) const {
    if (!valid_) return false;
    const double x = u - cx_, y = v - cy_;
    const double d2 = x * x + y * y;
    if (d2 > r_ * r_) return false;
    const double inner = r_ - kRobotStroke;
    if (inner < 0 || d2 > inner * inner) return true;
    // The heading segment: t along the heading, clamped to [0, r].
    const double t = std::clamp(x * dx_ + y * dy_, 0.0, r_);
    const double ex = x - t * dx_, ey = y - t * dy_;
    return ex * ex + ey * ey < (kRobotStroke / 2) * (kRobotStroke / 2);
  }

  /// Calls plot(px, py) for every pixel of a width x height image that shows the screen at
  /// `scale` image pixels per screen pixel and whose centre the image covers.
  template <typename Plot>
  void rasterize(int scale, int width, int height, Plot plot) const {
    if (!valid_ || scale < 1) return;
    // Image pixel p covers screen coordinates [p / scale - 0.5, (p + 1) / scale - 0.5).
    // Clamped in floating point first, so a robot far off the image converts safely.
    auto toImage = [scale](double v, int size) {
      return static_cast<long>(std::clamp(std::floor((v + 0.5) * scale), -1.0, static_cast<double>(size)));
    };
    const double reach = r_ + 1;
    const long x0 = std::max(0L, toImage(cx_ - reach, width)), x1 = std::min<long>(width - 1, toImage(cx_ + reach, width));
    const long y0 = std::max(0L, toImage(cy_ - reach, height)), y1 = std::min<long>(height - 1, toImage(cy_ + reach, height));
    for (long py = y0; py <= y1; ++py) {
      const double v = (static_cast<double>(py) + 0.5) / scale - 0.5;
      for (long px = x0; px <= x1; ++px) {
        const double u = (static_cast<double>(px) + 0.5) / scale - 0.5;
        if (covers(u, v)) plot(static_cast<int>(px), static_cast<int>(py));
      }
    }
  }

 private:
  bool valid_ = false;
  double cx_ = 0, cy_ = 0, r_ = 0, dx_ = 0, dy_ = -1;
};

}  // namespace rb::render
