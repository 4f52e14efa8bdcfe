#include "robot/robot_sim.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/runtime_error.h"
#include "robot/sim_constants.h"

namespace rb {

namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
/// The largest distance between a point and the centre of the pixel it rounds to.
constexpr double kRounding = 0.7072;
/// Nearest pixel of a coordinate.
int pixelOf(double v) { return static_cast<int>(std::floor(v + 0.5)); }
/// For a distance-sorted list: where each whole distance 0, 1, 2, ... starts.
template <typename Index, typename List>
std::vector<Index> startsOf(const List& list, double reach) {
  std::vector<Index> starts;
  size_t i = 0;
  for (int k = 0; k <= static_cast<int>(std::ceil(reach)) + 1; ++k) {
    while (i < list.size() && list[i].dist < k) ++i;
    starts.push_back(static_cast<Index>(i));
  }
  return starts;
}
/// First offset at least `d` from the centre, using the whole-distance starts to skip ahead.
template <typename List, typename Index>
size_t fromDistance(const List& list, const std::vector<Index>& starts, double d) {
  if (d <= 0) return 0;
  size_t k = std::min(static_cast<size_t>(d), starts.size() - 1);
  size_t i = starts[k];
  while (i < list.size() && list[i].dist < d - 1e-4) ++i;
  return i;
}
}  // namespace

SimRobot::SimRobot(Canvas& canvas, Rng& rng) : canvas_(canvas), rng_(rng), field_(canvas) {}

std::optional<QuietReadings> SimRobot::quietReadings() {
  if (!located_) return std::nullopt;
  return QuietReadings{bumper(), feel()};
}

void SimRobot::requireLocated() const {
  if (!located_) throw RuntimeError("the robot has not been placed: use rLocate x, y first");
}

Eigen::Vector2i SimRobot::centrePixel() const {
  return {pixelOf(pose_.pos.x()), pixelOf(pose_.pos.y())};
}

void SimRobot::prepareOffsets() {
  if (offsetsRadius_ == radius_) return;
  offsetsRadius_ = radius_;
  offsetsReach_ = radius_ + std::max({sim::kFeelReach, sim::kBumperReach, kRounding});
  byDistance_.clear();
  for (auto& b : byBearing_) b.clear();
  int r = static_cast<int>(std::ceil(offsetsReach_)) + 1;
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      double d = std::hypot(dx, dy);
      if (d > offsetsReach_ || d == 0) continue;
      double bearing = normalizeDegrees(std::atan2(dx, -dy) / kDegToRad);
      byDistance_.push_back({dx, dy, static_cast<float>(d), static_cast<float>(bearing)});
    }
  auto nearer = [](const Offset& a, const Offset& b) { return a.dist < b.dist; };
  std::stable_sort(byDistance_.begin(), byDistance_.end(), nearer);
  for (const Offset& o : byDistance_) byBearing_[static_cast<int>(o.bearing) % 360].push_back(o);
  distanceStart_ = startsOf<uint32_t>(byDistance_, offsetsReach_);
  for (int b = 0; b < 360; ++b) bearingStart_[b] = startsOf<uint16_t>(byBearing_[b], offsetsReach_);
  // A pixel a step sweeps the rim over is within (r - step, r] of the exact centre, so within
  // rounding of that from the centre pixel.
  const double inner = radius_ - sim::kMaxStep - kRounding - 1e-6, outer = radius_ + kRounding + 1e-6;
  rim_.clear();
  for (const Offset& o : byDistance_)
    if (o.dist >= inner && o.dist <= outer) rim_.push_back(o);
  std::stable_sort(rim_.begin(), rim_.end(), [](const Offset& a, const Offset& b) { return a.bearing < b.bearing; });
  rimStart_.assign(361, 0);
  size_t i = 0;
  for (int b = 0; b <= 360; ++b) {
    while (i < rim_.size() && rim_[i].bearing < b) ++i;
    rimStart_[static_cast<size_t>(b)] = static_cast<uint32_t>(i);
  }
  rimSlack_ = std::asin(std::min(1.0, kRounding / (radius_ - sim::kMaxStep))) / kDegToRad + 1e-3;
}

bool SimRobot::collides(const Eigen::Vector2d& pos) {
  prepareOffsets();
  int cx = pixelOf(pos.x()), cy = pixelOf(pos.y());
  // Every obstacle pixel is at least `clear` from the centre pixel; far from everything, one
  // lookup in the distance field decides.
  double clear = Canvas::inside(cx, cy) ? field_.distance(cx, cy) : 0;
  if (clear - kRounding > radius_) return false;
  if (field_.obstacle(cx, cy)) return true;
  double r2 = radius_ * radius_;
  for (auto it = byDistance_.begin() + static_cast<long>(fromDistance(byDistance_, distanceStart_, clear));
       it != byDistance_.end() && it->dist <= radius_ + kRounding; ++it) {
    int x = cx + it->dx, y = cy + it->dy;
    double dx = x - pos.x(), dy = y - pos.y();
    if (dx * dx + dy * dy <= r2 && field_.obstacle(x, y)) return true;
  }
  return false;
}

bool SimRobot::stepCrashes(const Eigen::Vector2d& from, const Eigen::Vector2d& to, const Eigen::Vector2d& dir) {
  prepareOffsets();
  int cx = pixelOf(to.x()), cy = pixelOf(to.y());
  double clear = Canvas::inside(cx, cy) ? field_.distance(cx, cy) : 0;
  if (clear - kRounding > radius_) return false;
  const double r2 = radius_ * radius_;
  const Eigen::Vector2d side(-dir.y(), dir.x());
  // The leading quadrant spans 45 degrees either side of the motion; seen from the centre
  // pixel a pixel's bearing may differ by rimSlack_, so the scan is that much wider and the
  // exact test decides.
  double mid = normalizeDegrees(std::atan2(dir.x(), -dir.y()) / kDegToRad);
  double lo = mid - 45 - rimSlack_, hi = mid + 45 + rimSlack_;
  int first = static_cast<int>(std::floor(lo)), last = static_cast<int>(std::floor(hi));
  for (int b = first; b <= last; ++b) {
    size_t bucket = static_cast<size_t>(((b % 360) + 360) % 360);
    for (uint32_t i = rimStart_[bucket]; i < rimStart_[bucket + 1]; ++i) {
      const Offset& o = rim_[i];
      int x = cx + o.dx, y = cy + o.dy;
      if (!field_.obstacle(x, y)) continue;
      double ux = x - to.x(), uy = y - to.y();
      if (ux * ux + uy * uy > r2) continue;                      // not inside after the step
      double f = ux * dir.x() + uy * dir.y(), s = ux * side.x() + uy * side.y();
      if (f < std::abs(s)) continue;                             // not in the leading quadrant
      double wx = x - from.x(), wy = y - from.y();
      if (wx * wx + wy * wy <= r2) continue;                     // already inside before it
      hitX_ = x;
      hitY_ = y;
      return true;
    }
  }
  return false;
}

void SimRobot::locate(double x, double y, double heading, double radius, Colour colour) {
  if (radius < sim::kMinRadius || radius > sim::kMaxRadius)
    throw RuntimeError("rLocate: the robot's radius must be between " +
                       std::to_string(static_cast<int>(sim::kMinRadius)) + " and " +
                       std::to_string(static_cast<int>(sim::kMaxRadius)));
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(heading))
    throw RuntimeError("rLocate: the position or heading is not a number");
  // A robot that would stick out of the screen goes just inside, touching the edge: its disc
  // then covers the outermost pixels but not the wall beyond them (at -1 and 800 or 600).
  double px = std::clamp(x, radius, Canvas::kWidth - 1 - radius);
  double py = std::clamp(y, radius, Canvas::kHeight - 1 - radius);
  double oldRadius = radius_;
  radius_ = radius;
  if (collides({px, py})) {
    radius_ = oldRadius;
    throw RuntimeError("rLocate: the robot at (" + std::to_string(std::lround(x)) + ", " +
                       std::to_string(std::lround(y)) + ") would overlap an obstacle");
  }
  pose_.pos = {px, py};
  pose_.heading = normalizeDegrees(heading);
  colour_ = colour;
  located_ = true;
  canvas_.trailEnd();
  penAt_ = pose_.pos;
  if (penDown_) extendTrail();
}

double SimRobot::applySlip(double amount) {
  if (slip_ <= 0) return amount;
  double u = (rng_.unit() * 2 - 1) * slip_ / 100.0;
  return amount * (1 + u);
}

void SimRobot::extendTrail() {
  // The pen draws in the first invisible colour (so the robot does not see its own trail), or
  // in the current drawing colour when no colour is invisible. The trail is one line: it goes
  // on from where it ended, whatever was drawn in between; a new colour or width starts a new
  // polyline at the same point.
  Colour c = trailColour();
  int width = canvas_.lineWidth;
  if (!canvas_.trailOpen() || canvas_.trailColour() != c || canvas_.trailWidth() != width)
    canvas_.trailStart(penAt_.x(), penAt_.y(), width, c);
  // A trail in an obstacle colour changes a few pixels around the segment; the obstacle field
  // learns where from the canvas and catches up there.
  canvas_.trailTo(pose_.pos.x(), pose_.pos.y());
  penAt_ = pose_.pos;
}

void SimRobot::setPen(bool down) {
  if (down && !penDown_) penAt_ = pose_.pos;
  penDown_ = down;
  if (!down) canvas_.trailEnd();
  if (down && located_) extendTrail();
}

Colour SimRobot::trailColour() const {
  const auto& inv = canvas_.invisible();
  return inv.empty() ? canvas_.foreground : inv.front();
}

namespace {
std::string colourName(Colour c) {
  static const char* kNames[16] = {"Black", "Blue", "Green", "Cyan", "Red", "Magenta", "Brown",
                                   "Gray", "DarkGray", "LightBlue", "LightGreen", "LightCyan",
                                   "LightRed", "LightMagenta", "Yellow", "White"};
  if (c < 16) return kNames[c];
  return "RGB(" + std::to_string(c & 0xff) + ", " + std::to_string((c >> 8) & 0xff) + ", " +
         std::to_string((c >> 16) & 0xff) + ")";
}
}  // namespace

std::string SimRobot::crashMessage() const {
  std::string msg = "robot crashed into an obstacle";
  if (!Canvas::inside(hitX_, hitY_)) return msg + ": the edge of the screen";
  Colour c = canvas_.at(hitX_, hitY_);
  std::string name = colourName(c);
  if (penDown_ && c == trailColour())
    return msg + ": its own pen trail (colour " + name + "); add 'rInvisible " + name +
           "' before 'rPen down' so the robot does not see its trail";
  return msg + ": colour " + name + " at (" + std::to_string(hitX_) + ", " + std::to_string(hitY_) + ")";
}

double SimRobot::forward(double distance, const StepFn& onStep) {
  requireLocated();
  distance = applySlip(distance);
  if (!std::isfinite(distance)) throw RuntimeError("rForward: the distance is not a number");
  double length = std::abs(distance);
  int steps = static_cast<int>(std::ceil(length / sim::kMaxStep));
  if (steps == 0) return distance;
  // Forward the front quadrant of the rim leads, backing up the rear one.
  const Eigen::Vector2d dir = headingVector(pose_.heading) * (distance < 0 ? -1.0 : 1.0);
  Eigen::Vector2d step = dir * (length / steps);
  // The pen draws as the robot goes when someone watches, or when its trail is an obstacle (the
  // robot runs into it when it drives back over it); otherwise the whole segment is drawn once
  // at the end.
  bool trailEachStep = penDown_ && (onStep || canvas_.isObstacleColour(trailColour()));
  prepareOffsets();
  int cx = pixelOf(pose_.pos.x()), cy = pixelOf(pose_.pos.y());
  // When the nearest obstacle is farther than the whole move plus the radius, no step can
  // touch it.
  double clear = Canvas::inside(cx, cy) ? field_.distance(cx, cy) : 0;
  bool freeRun = !trailEachStep && clear - 2 * kRounding - radius_ > length;
  for (int i = 0; i < steps; ++i) {
    Eigen::Vector2d next = pose_.pos + step;
    if (!freeRun && stepCrashes(pose_.pos, next, dir)) {
      if (penDown_ && !trailEachStep) extendTrail();
      throw RuntimeError(crashMessage(), "rb-robot-crash");
    }
    pose_.pos = next;
    if (trailEachStep) extendTrail();
    if (onStep) onStep();
  }
  travelled_ += length;
  if (penDown_ && !trailEachStep) extendTrail();
  return distance;
}

double SimRobot::turn(double degrees, const StepFn& onStep) {
  requireLocated();
  degrees = applySlip(degrees);
  if (!std::isfinite(degrees)) throw RuntimeError("rTurn: the angle is not a number");
  turned_ += std::abs(degrees);
  if (!onStep) {
    pose_.heading = normalizeDegrees(pose_.heading + degrees);
    return degrees;
  }
  int steps = static_cast<int>(std::ceil(std::abs(degrees)));
  if (steps == 0) return degrees;
  double each = degrees / steps;
  double start = pose_.heading;
  for (int i = 1; i <= steps; ++i) {
    pose_.heading = normalizeDegrees(start + each * i);
    onStep();
  }
  return degrees;
}

int SimRobot::bumper() {
  requireLocated();
  prepareOffsets();
  // The bumpers sit on the rim: they feel obstacle pixels within kBumperReach of the edge,
  // inside or outside it (not what lies deep under the robot), measured from the exact centre,
  // so that a step that crashes always had the bumper of its leading quadrant pressed before
  // it (docs/robot.md, "Collisions").
  const double reach = radius_ + sim::kBumperReach, inner = radius_ - sim::kBumperReach;
  Eigen::Vector2i c = centrePixel();
  const Eigen::Vector2d off = pose_.pos - c.cast<double>();
  // Distances from the centre pixel differ from those from the exact centre by at most this.
  const double slack = off.norm() + 1e-9;
  double clear = Canvas::inside(c.x(), c.y()) ? field_.distance(c.x(), c.y()) : 0;
  if (clear - slack > reach) return 0;
  const Eigen::Vector2d fwd = headingVector(pose_.heading), right(-fwd.y(), fwd.x());
  const double reach2 = reach * reach, inner2 = inner > 0 ? inner * inner : -1;
  constexpr double kTie = 1e-9;  // both edges of the front and rear quadrants belong to them
  int bits = 0;
  double from = std::max(clear, inner) - slack;
  for (auto it = byDistance_.begin() + static_cast<long>(fromDistance(byDistance_, distanceStart_, from));
       it != byDistance_.end() && it->dist <= reach + slack; ++it) {
    if (!field_.obstacle(c.x() + it->dx, c.y() + it->dy)) continue;
    double vx = it->dx - off.x(), vy = it->dy - off.y();
    double d2 = vx * vx + vy * vy;
    if (d2 > reach2 || d2 < inner2) continue;
    double f = vx * fwd.x() + vy * fwd.y(), s = vx * right.x() + vy * right.y();
    if (f + kTie >= std::abs(s)) bits |= sim::kBumperFront;
    else if (-f + kTie >= std::abs(s)) bits |= sim::kBumperRear;
    else bits |= s > 0 ? sim::kBumperRight : sim::kBumperLeft;
    if (bits == 15) break;
  }
  return bits;
}

int SimRobot::feel() {
  requireLocated();
  prepareOffsets();
  double reach = radius_ + sim::kFeelReach;
  Eigen::Vector2i c = centrePixel();
  double clear = Canvas::inside(c.x(), c.y()) ? field_.distance(c.x(), c.y()) : 0;
  if (clear > reach) return 0;
  int bits = 0;
  for (int k = 0; k < 5; ++k) {
    double lo = normalizeDegrees(pose_.heading + sim::kFeelAngles[k] - sim::kFeelHalfAngle);
    double width = 2 * sim::kFeelHalfAngle;
    // The cone covers whole-degree buckets from lo's to lo + width's; edge buckets hold pixels
    // outside it, so each pixel's bearing is checked too.
    int first = static_cast<int>(lo);
    int count = static_cast<int>(std::floor(lo + width)) - first + 1;
    bool hit = false;
    for (int b = 0; b < count && !hit; ++b) {
      int index = (first + b) % 360;
      const std::vector<Offset>& bucket = byBearing_[index];
      bool edge = b == 0 || b == count - 1;
      for (auto it = bucket.begin() + static_cast<long>(fromDistance(bucket, bearingStart_[index], clear));
           it != bucket.end() && it->dist <= reach; ++it) {
        if (edge) {
          double rel = it->bearing - lo;  // in (-360, 360): one wrap is enough
          if (rel < 0) rel += 360;
          if (rel > width) continue;
        }
        if (field_.obstacle(c.x() + it->dx, c.y() + it->dy)) {
          hit = true;
          break;
        }
      }
    }
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

int SimRobot::compass() {
  requireLocated();
  return static_cast<int>(std::lround(pose_.heading)) % 360;
}

int SimRobot::gpsX() {
  requireLocated();
  return static_cast<int>(std::lround(pose_.pos.x()));
}

int SimRobot::gpsY() {
  requireLocated();
  return static_cast<int>(std::lround(pose_.pos.y()));
}

double SimRobot::chargeLevel() {
  double used = travelled_ / sim::kChargePixelsPerPercent + turned_ / sim::kChargeDegreesPerPercent;
  return std::max(0.0, sim::kChargeFull - used);
}

}  // namespace rb
