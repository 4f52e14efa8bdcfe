#include "robot_sim.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "runtime_error.h"
#include "sim_constants.h"

namespace rb {

namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
/// The largest distance between a point and the centre of the pixel it rounds to.
constexpr double kRounding = 0.7072;
}  // namespace

double normalizeDegrees(double d) {
  double r = std::fmod(d, 360.0);
  if (r < 0) r += 360.0;
  if (r >= 360.0) r = 0;
  return r;
}

Eigen::Vector2d headingVector(double degrees) {
  // Heading 0 points up (-y); the rotation is clockwise on screen, where y grows downward.
  return Eigen::Rotation2Dd(degrees * kDegToRad) * Eigen::Vector2d(0, -1);
}

SimRobot::SimRobot(Canvas& canvas, Rng& rng) : canvas_(canvas), rng_(rng), field_(canvas) {}

void SimRobot::requireLocated() const {
  if (!located_) throw RuntimeError("the robot has not been placed: use rLocate x, y first");
}

Eigen::Vector2i SimRobot::centrePixel() const {
  return {static_cast<int>(std::lround(pose_.pos.x())), static_cast<int>(std::lround(pose_.pos.y()))};
}

bool SimRobot::collides(const Eigen::Vector2d& pos) {
  int cx = static_cast<int>(std::lround(pos.x())), cy = static_cast<int>(std::lround(pos.y()));
  // Far from everything: one lookup in the distance field decides.
  if (Canvas::inside(cx, cy) && field_.distance(cx, cy) - kRounding > radius_) return false;
  double r2 = radius_ * radius_;
  int r = static_cast<int>(std::ceil(radius_)) + 1;
  for (int y = cy - r; y <= cy + r; ++y) {
    double dy = y - pos.y();
    for (int x = cx - r; x <= cx + r; ++x) {
      double dx = x - pos.x();
      if (dx * dx + dy * dy <= r2 && canvas_.isObstacle(x, y)) return true;
    }
  }
  return false;
}

void SimRobot::locate(double x, double y, double heading, double radius, Colour colour) {
  if (radius < sim::kMinRadius || radius > sim::kMaxRadius)
    throw RuntimeError("rLocate: the robot's radius must be between " +
                       std::to_string(static_cast<int>(sim::kMinRadius)) + " and " +
                       std::to_string(static_cast<int>(sim::kMaxRadius)));
  double oldRadius = radius_;
  radius_ = radius;
  if (collides({x, y})) {
    radius_ = oldRadius;
    throw RuntimeError("rLocate: the robot at (" + std::to_string(std::lround(x)) + ", " +
                       std::to_string(std::lround(y)) + ") would overlap an obstacle");
  }
  pose_.pos = {x, y};
  pose_.heading = normalizeDegrees(heading);
  colour_ = colour;
  located_ = true;
  canvas_.trailEnd();
  if (penDown_) extendTrail();
}

double SimRobot::applySlip(double amount) {
  if (slip_ <= 0) return amount;
  double u = (rng_.unit() * 2 - 1) * slip_ / 100.0;
  return amount * (1 + u);
}

void SimRobot::extendTrail() {
  // The pen draws in the first invisible colour (so the robot does not see its own trail), or
  // in the current drawing colour when no colour is invisible.
  const auto& inv = canvas_.invisible();
  Colour c = inv.empty() ? canvas_.foreground : inv.front();
  const auto& ops = canvas_.displayList();
  bool open = !ops.empty() && ops.back().kind == DrawOp::Trail && ops.back().colour == c &&
              ops.back().width == canvas_.lineWidth;
  if (open) {
    canvas_.trailTo(pose_.pos.x(), pose_.pos.y());
  } else {
    canvas_.trailStart(pose_.pos.x(), pose_.pos.y(), canvas_.lineWidth, c);
    canvas_.trailTo(pose_.pos.x(), pose_.pos.y());
  }
}

void SimRobot::setPen(bool down) {
  penDown_ = down;
  if (!down) canvas_.trailEnd();
  if (down && located_) extendTrail();
}

double SimRobot::forward(double distance, const std::function<void()>& onStep) {
  requireLocated();
  distance = applySlip(distance);
  if (!std::isfinite(distance)) throw RuntimeError("rForward: the distance is not a number");
  double length = std::abs(distance);
  int steps = static_cast<int>(std::ceil(length / sim::kMaxStep));
  if (steps == 0) return distance;
  Eigen::Vector2d step = headingVector(pose_.heading) * (distance / steps);
  for (int i = 0; i < steps; ++i) {
    Eigen::Vector2d next = pose_.pos + step;
    if (collides(next)) throw RuntimeError("robot crashed into an obstacle");
    pose_.pos = next;
    travelled_ += step.norm();
    if (penDown_) extendTrail();
    if (onStep) onStep();
  }
  return distance;
}

double SimRobot::turn(double degrees, const std::function<void()>& onStep) {
  requireLocated();
  degrees = applySlip(degrees);
  if (!std::isfinite(degrees)) throw RuntimeError("rTurn: the angle is not a number");
  int steps = static_cast<int>(std::ceil(std::abs(degrees)));
  if (steps == 0) return degrees;
  double each = degrees / steps;
  double start = pose_.heading;
  for (int i = 1; i <= steps; ++i) {
    pose_.heading = normalizeDegrees(start + each * i);
    if (onStep) onStep();
  }
  turned_ += std::abs(degrees);
  return degrees;
}

const std::vector<SimRobot::Offset>& SimRobot::offsetsWithin(double reach) {
  if (reach == cachedReach_) return offsets_;
  offsets_.clear();
  int r = static_cast<int>(std::ceil(reach)) + 1;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      double d = std::hypot(dx, dy);
      if (d > reach || d == 0) continue;
      double bearing = normalizeDegrees(std::atan2(dx, -dy) / kDegToRad);
      offsets_.push_back({dx, dy, static_cast<float>(d), static_cast<float>(bearing)});
    }
  std::sort(offsets_.begin(), offsets_.end(), [](const Offset& a, const Offset& b) { return a.bearing < b.bearing; });
  cachedReach_ = reach;
  return offsets_;
}

int SimRobot::bumper() {
  requireLocated();
  double reach = radius_ + sim::kBumperReach;
  Eigen::Vector2i c = centrePixel();
  if (Canvas::inside(c.x(), c.y()) && field_.distance(c.x(), c.y()) - kRounding > reach) return 0;
  int bits = 0;
  for (const Offset& o : offsetsWithin(reach)) {
    if (!canvas_.isObstacle(c.x() + o.dx, c.y() + o.dy)) continue;
    double rel = normalizeDegrees(o.bearing - pose_.heading);
    if (rel > 180) rel -= 360;  // (-180, 180]
    if (rel >= -45 && rel <= 45) bits |= sim::kBumperFront;
    else if (rel > 45 && rel < 135) bits |= sim::kBumperRight;
    else if (rel < -45 && rel > -135) bits |= sim::kBumperLeft;
    else bits |= sim::kBumperRear;
    if (bits == 15) break;
  }
  return bits;
}

int SimRobot::feel() {
  requireLocated();
  double reach = radius_ + sim::kFeelReach;
  Eigen::Vector2i c = centrePixel();
  if (Canvas::inside(c.x(), c.y()) && field_.distance(c.x(), c.y()) - kRounding > reach) return 0;
  const std::vector<Offset>& offs = offsetsWithin(reach);
  int bits = 0;
  for (int k = 0; k < 5; ++k) {
    double centre = normalizeDegrees(pose_.heading + sim::kFeelAngles[k]);
    double lo = centre - sim::kFeelHalfAngle, hi = centre + sim::kFeelHalfAngle;
    // The cone may wrap past 0/360: scan it as one or two bearing ranges.
    auto scan = [&](double from, double to) {
      auto it = std::lower_bound(offs.begin(), offs.end(), from,
                                 [](const Offset& o, double b) { return o.bearing < b; });
      for (; it != offs.end() && it->bearing <= to; ++it)
        if (canvas_.isObstacle(c.x() + it->dx, c.y() + it->dy)) return true;
      return false;
    };
    bool hit = lo < 0 ? scan(lo + 360, 360) || scan(0, hi)
               : hi >= 360 ? scan(lo, 360) || scan(0, hi - 360)
                           : scan(lo, hi);
    if (hit) bits |= sim::kFeelBits[k];
  }
  return bits;
}

int SimRobot::sense() {
  requireLocated();
  Eigen::Vector2d fwd = headingVector(pose_.heading);
  Eigen::Vector2d right = headingVector(pose_.heading + 90);
  Eigen::Vector2d mid = pose_.pos + fwd * (radius_ * sim::kSenseAhead);
  Eigen::Vector2d side = right * (radius_ * sim::kSenseSide);
  auto onLine = [&](const Eigen::Vector2d& p) {
    int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    return Canvas::inside(x, y) && canvas_.at(x, y) != canvas_.background();
  };
  int bits = 0;
  if (onLine(mid - side)) bits |= sim::kSenseLeft;
  if (onLine(mid)) bits |= sim::kSenseMiddle;
  if (onLine(mid + side)) bits |= sim::kSenseRight;
  return bits;
}

SimRobot::RayHit SimRobot::castRay(double absoluteAngle) {
  Eigen::Vector2d dir = headingVector(absoluteAngle);
  double t = radius_;
  const double limit = radius_ + 2000;  // longer than the screen's diagonal
  while (t < limit) {
    Eigen::Vector2d p = pose_.pos + dir * t;
    int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    if (!Canvas::inside(x, y)) return {t, static_cast<Colour>(sim::kEdgeColour), true};
    if (canvas_.isObstacleColour(canvas_.at(x, y))) return {t, canvas_.at(x, y), false};
    // Open space: jump ahead by whole pixels the distance field guarantees are free, so the
    // result is the same as marching one pixel at a time.
    double clear = std::floor(field_.distance(x, y) - 1.5);
    t += clear > 1 ? clear : 1;
  }
  return {limit, static_cast<Colour>(sim::kEdgeColour), true};
}

double SimRobot::range(double relativeAngle) {
  requireLocated();
  return std::floor(castRay(pose_.heading + relativeAngle).distance - radius_);
}

Colour SimRobot::look(double relativeAngle) {
  requireLocated();
  return castRay(pose_.heading + relativeAngle).colour;
}

double SimRobot::beacon(Colour colour) {
  requireLocated();
  // Invisible colours are looked through, the beacon colour is seen even if invisible, and
  // anything else opaque in front of it hides it.
  Eigen::Vector2d dir = headingVector(pose_.heading);
  for (double t = radius_; t < radius_ + 2000; t += 1) {
    Eigen::Vector2d p = pose_.pos + dir * t;
    int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    if (!Canvas::inside(x, y)) return 0;
    Colour c = canvas_.at(x, y);
    if (c == colour) return std::floor(t - radius_) + 1;
    if (canvas_.isObstacleColour(c)) return 0;
  }
  return 0;
}

int SimRobot::compass() const {
  requireLocated();
  return static_cast<int>(std::lround(pose_.heading)) % 360;
}

int SimRobot::gpsX() const {
  requireLocated();
  return static_cast<int>(std::lround(pose_.pos.x()));
}

int SimRobot::gpsY() const {
  requireLocated();
  return static_cast<int>(std::lround(pose_.pos.y()));
}

double SimRobot::chargeLevel() const {
  double used = travelled_ / sim::kChargePixelsPerPercent + turned_ / sim::kChargeDegreesPerPercent;
  return std::max(0.0, sim::kChargeFull - used);
}

}  // namespace rb
