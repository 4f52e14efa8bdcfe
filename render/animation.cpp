#include "animation.h"

#include <gif_lib.h>
#include <png.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "json_text.h"
#include "robot_image.h"

namespace rb::render {

namespace {

constexpr int kW = Canvas::kWidth;
constexpr int kH = Canvas::kHeight;
constexpr size_t kPixels = static_cast<size_t>(kW) * kH;

RobotView robotOf(const RecordedStep& s) {
  RobotView v;
  v.visible = s.located;
  v.x = s.x;
  v.y = s.y;
  v.heading = s.heading;
  v.radius = s.radius;
  v.colour = s.robotColour;
  return v;
}

// The page draws the robot itself from the pose, as render/robot_image.h does: the centre and
// radius in 1/1024 pixels, the heading's unit vector in 1/2^20, all exact in a double, so the
// page's arithmetic (IEEE doubles, no fused multiply-add: this file is compiled with
// -ffp-contract=off) is the same as PlayerRobot's here. Where those rounded values cover other
// pixels than the exact pose does (a pixel centre within a rounding of the rim), the step
// carries the pixels that differ, so the page's robot is rb render's, pixel for pixel.
constexpr double kPosQ = 1024;
constexpr double kDirQ = 1048576;
constexpr double kMaxQuantized = 1e15;  // below 2^53: exact in the page's numbers

struct QuantizedPose {
  bool visible = false;  ///< RobotImage draws it and the values fit
  int64_t x = 0, y = 0, r = 0, dx = 0, dy = 0, heading = 0;
};

int64_t quantize(double v, double scale) {
  const double q = v * scale;
  return std::isfinite(q) && std::fabs(q) < kMaxQuantized ? std::llround(q) : 0;
}

QuantizedPose quantizePose(const RecordedStep& s) {
  QuantizedPose q;
  q.x = quantize(s.x, kPosQ);
  q.y = quantize(s.y, kPosQ);
  q.r = quantize(s.radius, kPosQ);
  q.heading = quantize(std::isfinite(s.heading) ? std::fmod(s.heading, 360.0) : 0, kPosQ);
  const RobotImage image(robotOf(s));
  if (image.empty()) return q;
  auto fits = [](double v, double scale) { return std::fabs(v * scale) < kMaxQuantized; };
  q.visible = fits(image.centreX(), kPosQ) && fits(image.centreY(), kPosQ) && fits(image.radius(), kPosQ);
  q.dx = quantize(image.headingX(), kDirQ);
  q.dy = quantize(image.headingY(), kDirQ);
  return q;
}


// ---------------------------------------------------------------- glides

/// The heading `degrees` as a unit vector (0 up, clockwise), by the same operations as the HTML
/// player's headingUnit (a quadrant, then Taylor series to r^13 on |r| <= pi/4: within 1e-13 of
/// sin and cos), so the page's glides are the GIF's pixel for pixel.
void headingUnit(double degrees, double& dx, double& dy) {
  const double q = std::floor(degrees / 90 + 0.5);
  const double r = (degrees - q * 90) * (3.141592653589793 / 180);
  const double r2 = r * r;
  const double s = r * (1 - r2 / 6 * (1 - r2 / 20 * (1 - r2 / 42 * (1 - r2 / 72 * (1 - r2 / 110 * (1 - r2 / 156))))));
  const double c = 1 - r2 / 2 * (1 - r2 / 12 * (1 - r2 / 30 * (1 - r2 / 56 * (1 - r2 / 90 * (1 - r2 / 132)))));
  const long long k = ((static_cast<long long>(q) % 4) + 4) % 4;
  const double sinH = k == 0 ? s : k == 1 ? c : k == 2 ? -s : -c;
  const double cosH = k == 0 ? c : k == 1 ? -s : k == 2 ? -c : s;
  dx = sinH;
  dy = -cosH;
}

/// The turn from heading a to heading b the short way, in (-180, 180].
double shortTurn(double a, double b) {
  double d = b - a;
  if (d > 180) d -= 360;
  else if (d <= -180) d += 360;
  return d;
}

struct GlideEnds {
  double ax = 0, ay = 0, bx = 0, by = 0, r = 0, dx = 0, dy = 0, h0 = 0, turn = 0;
  bool rotate = false;
  double extent = 0;  ///< 0: no glide
};

GlideEnds glideEnds(const Recording& rec, size_t i) {
  GlideEnds g;
  const std::vector<RecordedStep>& steps = rec.steps();
  if (i + 1 >= steps.size()) return g;
  const RecordedStep &a = steps[i], &b = steps[i + 1];
  if (!a.located || !b.located || a.radius != b.radius || a.robotColour != b.robotColour) return g;
  const QuantizedPose qa = quantizePose(a), qb = quantizePose(b);
  if (!qa.visible || !qb.visible || qa.r != qb.r) return g;
  g.ax = static_cast<double>(qa.x) / kPosQ;
  g.ay = static_cast<double>(qa.y) / kPosQ;
  g.bx = static_cast<double>(qb.x) / kPosQ;
  g.by = static_cast<double>(qb.y) / kPosQ;
  g.r = static_cast<double>(qa.r) / kPosQ;
  g.dx = static_cast<double>(qa.dx) / kDirQ;
  g.dy = static_cast<double>(qa.dy) / kDirQ;
  g.h0 = static_cast<double>(qa.heading) / kPosQ;
  if (qa.x != qb.x || qa.y != qb.y) {
    if (qa.heading != qb.heading || qa.dx != qb.dx || qa.dy != qb.dy) return g;  // moved and turned
    g.extent = std::hypot(g.bx - g.ax, g.by - g.ay);
  } else if (qa.heading != qb.heading) {
    if (a.frame != b.frame) return g;  // a turn that changed the screen: not one statement's turn
    g.rotate = true;
    g.turn = shortTurn(g.h0, static_cast<double>(qb.heading) / kPosQ);
    g.extent = std::fabs(g.turn);
  }
  if (!std::isfinite(g.extent)) g.extent = 0;
  return g;
}

GlidePose poseOf(const GlideEnds& g, uint32_t part, uint32_t parts) {
  GlidePose p;
  const double t = static_cast<double>(part) / static_cast<double>(parts);
  p.radius = g.r;
  if (g.rotate) {
    p.x = g.ax;
    p.y = g.ay;
    headingUnit(g.h0 + g.turn * t, p.dx, p.dy);
  } else {
    p.x = g.ax + (g.bx - g.ax) * t;
    p.y = g.ay + (g.by - g.ay) * t;
    p.dx = g.dx;
    p.dy = g.dy;
  }
  return p;
}

/// Whether screen pixel (px, py) that the move changes shows part of the way: its projection on
/// the move at most the robot's (the page's reveal does the same operations).
bool revealed(const GlideEnds& g, double t, int px, int py) {
  const double ux = g.bx - g.ax, uy = g.by - g.ay;
  const double l2 = ux * ux + uy * uy;
  return (static_cast<double>(px) - g.ax) * ux + (static_cast<double>(py) - g.ay) * uy <= t * l2;
}

/// Whether two steps show the same picture: the same keyframe and the same robot image.
bool sameLook(const RecordedStep& a, const RecordedStep& b) {
  if (a.frame != b.frame || a.located != b.located) return false;
  if (!a.located) return true;
  return a.x == b.x && a.y == b.y && a.heading == b.heading && a.radius == b.radius &&
         a.robotColour == b.robotColour;
}

/// `most` of `from`, evenly spread by position, the first and the last kept.
std::vector<size_t> evenly(const std::vector<size_t>& from, size_t most) {
  if (from.size() <= most) return from;
  std::vector<size_t> out;
  out.reserve(most);
  const size_t n = from.size() - 1, m = most - 1;
  for (size_t k = 0; k < most; ++k) out.push_back(from[(k * n + m / 2) / m]);
  return out;
}

}  // namespace

FrameTimes animationTimes(const Recording& recording, const AnimationOptions& options) {
  FrameTimes out;
  const std::vector<RecordedStep>& steps = recording.steps();
  if (steps.empty()) return out;
  const double fps = std::clamp(std::isfinite(options.fps) ? options.fps : 10.0, kMinFps, kMaxFps);
  const size_t most = std::max<size_t>(2, options.maxFrames);
  const uint64_t last = steps.back().step;
  if (options.duration) {
    // Frames at even statement counts, so that time on screen follows the run's statements.
    const double seconds = std::clamp(*options.duration, 1 / kMaxFps, kMaxDuration);
    const size_t count = std::clamp<size_t>(static_cast<size_t>(std::llround(seconds * fps)) + 1, 2, most);
    for (size_t k = 0; k < count; ++k) {
      // The statement reached by frame k's time (the end at the last frame).
      const uint64_t target = static_cast<uint64_t>(
          std::floor(static_cast<long double>(last) * static_cast<long double>(k) / static_cast<long double>(count - 1)));
      const size_t i = recording.stepAt(target);
      if (!out.steps.empty() && out.steps.back() == i) continue;  // the one before lasts longer
      out.steps.push_back(i);
      out.seconds.push_back(seconds * static_cast<double>(k) / static_cast<double>(count - 1));
    }
    if (out.steps.back() != steps.size() - 1) {  // rounding never leaves it out, but be sure
      out.steps.push_back(steps.size() - 1);
      out.seconds.push_back(seconds);
    }
    out.part.assign(out.steps.size(), 0);
    out.parts.assign(out.steps.size(), 1);
    return out;
  }
  std::vector<size_t> candidates;
  if (options.every) {
    // The step in effect at statements 0, N, 2N..: the kept step at or before each. The next
    // one that differs is the first multiple of N at or after the next kept step.
    const uint64_t every = std::max<uint64_t>(1, *options.every);
    uint64_t target = 0;
    for (;;) {
      const size_t i = recording.stepAt(target);
      if (candidates.empty() || candidates.back() != i) candidates.push_back(i);
      if (i + 1 >= steps.size()) break;
      const uint64_t next = steps[i + 1].step;
      const uint64_t multiple = next / every + (next % every != 0 ? 1 : 0);
      if (multiple > last / every) break;  // past the end (and no overflow below)
      target = multiple * every;
    }
  } else {
    // One frame per step whose picture differs from the step before.
    candidates.push_back(0);
    for (size_t i = 1; i < steps.size(); ++i)
      if (!sameLook(steps[i], steps[i - 1])) candidates.push_back(i);
  }
  if (candidates.back() != steps.size() - 1) candidates.push_back(steps.size() - 1);
  // Glides: the moves and turns into a frame (from the recorded step before it), in frames of
  // their own, while all the frames fit in `most` (their steps doubled until they do).
  std::vector<double> glideUnits(candidates.size(), 0);  // the extent in steps of the glide, per frame
  if (options.glide && !options.every && candidates.size() < most) {
    for (size_t c = 1; c < candidates.size(); ++c) {
      bool turn = false;
      const double extent = glideExtent(recording, candidates[c] - 1, &turn);
      glideUnits[c] = extent / (turn ? kGlideDegrees : kGlidePixels);
    }
  }
  auto partsOf = [](double units, double factor) {
    const double parts = std::ceil(units / factor);
    return parts > 1 ? static_cast<size_t>(std::min(parts, 1e9)) : size_t{1};
  };
  double factor = 1;
  for (;; factor *= 2) {
    size_t total = candidates.size();
    for (double u : glideUnits) total += partsOf(u, factor) - 1;
    if (total <= most || factor > 1e15) break;
  }
  const std::vector<size_t> chosen = evenly(candidates, most);
  const bool glides = chosen.size() == candidates.size();
  for (size_t c = 0; c < chosen.size(); ++c) {
    const size_t parts = glides ? partsOf(glideUnits[c], factor) : 1;
    for (size_t j = 1; j < parts; ++j) {
      out.steps.push_back(chosen[c] - 1);
      out.part.push_back(static_cast<uint32_t>(j));
      out.parts.push_back(static_cast<uint32_t>(parts));
    }
    out.steps.push_back(chosen[c]);
    out.part.push_back(0);
    out.parts.push_back(1);
  }
  for (size_t k = 0; k < out.steps.size(); ++k) out.seconds.push_back(static_cast<double>(k) / fps);
  return out;
}

double glideExtent(const Recording& recording, size_t step, bool* turn) {
  const GlideEnds g = glideEnds(recording, step);
  if (turn) *turn = g.rotate;
  return g.extent;
}

GlidePose glidePose(const Recording& recording, size_t step, uint32_t part, uint32_t parts) {
  return poseOf(glideEnds(recording, step), part, std::max<uint32_t>(parts, 1));
}

std::vector<size_t> animationFrames(const Recording& recording, const AnimationOptions& options) {
  return animationTimes(recording, options).steps;
}

RgbImage frameImage(const Recording& recording, size_t step, int scale) {
  const RecordedStep& s = recording.steps().at(step);
  const std::vector<Colour> screen = recording.screen(s.frame);
  const Pixels pixels(screen.begin(), screen.end());
  return composeImage(pixels, robotOf(s), scale);
}

namespace {

// ---------------------------------------------------------------- frames as changes

/// What changed in the picture from one frame to the next: the smallest box of image pixels
/// holding every pixel that differs, the box's new pixels (0xRRGGBB, row-major) and which of
/// them differ. `width` 0: nothing changed. The first picture is all of it: `whole` points to
/// its pixels (not copied: at --scale 8 it is 123 MB) and every pixel counts as changed.
struct FrameChange {
  int x = 0, y = 0, width = 0, height = 0;
  std::vector<uint32_t> rgb;
  std::vector<uint8_t> changed;
  const std::vector<uint32_t>* whole = nullptr;

  size_t area() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
  uint32_t pixel(size_t i) const { return whole ? (*whole)[i] : rgb[i]; }
  bool changedAt(size_t i) const { return whole || changed[i]; }
};

/// Walks the recorded steps in order and gives each one's picture as what changed since the
/// last: the keyframes are applied one after the other (each once), noting the screen pixels
/// that change; only those and the pixels the robot covered or covers now are composed and
/// compared with the picture shown. The pictures are frameImage()'s, pixel for pixel.
class Composer {
 public:
  Composer(const Recording& recording, int scale)
      : rec_(recording), scale_(std::clamp(scale, 1, kMaxScale)), width_(kW * scale_), height_(kH * scale_) {}

  int width() const { return width_; }
  int height() const { return height_; }

  FrameChange moveTo(size_t stepIndex) {
    const RecordedStep& s = rec_.steps().at(stepIndex);
    advance(s.frame);
    return compose(RobotImage(robotOf(s)), colourToRgb(s.robotColour));
  }

  /// Part `part` of `parts` of the way from step `stepIndex` to the next (glideImage()). The
  /// glide's frames of one move come in order after the step's own (the screen's pixels
  /// revealed so far stay; the next step's keyframe brings the rest).
  FrameChange glideTo(size_t stepIndex, uint32_t part, uint32_t parts) {
    const std::vector<RecordedStep>& steps = rec_.steps();
    const RecordedStep& s = steps.at(stepIndex);
    advance(s.frame);
    const GlideEnds g = glideEnds(rec_, stepIndex);
    if (g.extent <= 0 || parts == 0) return moveTo(stepIndex);
    const double t = static_cast<double>(part) / static_cast<double>(parts);
    const std::vector<RecordedFrame>& frames = rec_.frames();
    const uint32_t to = std::min<uint32_t>(steps[stepIndex + 1].frame, static_cast<uint32_t>(frames.size()));
    for (size_t f = static_cast<size_t>(applied_ + 1); f <= to && f < frames.size(); ++f) {
      size_t at = 0;
      for (const ScreenRun& r : frames[f].runs) {
        const size_t n = std::min<size_t>(r.count, kPixels - at);
        if (r.colour != kSameColour)
          for (size_t p = at; p < at + n; ++p)
            if (revealed(g, t, static_cast<int>(p % kW), static_cast<int>(p / kW))) set(p, r.colour);
        at += n;
      }
    }
    const GlidePose pose = poseOf(g, part, parts);
    return compose(RobotImage::fromVector(pose.x, pose.y, pose.radius, pose.dx, pose.dy), colourToRgb(s.robotColour));
  }

  /// The picture last given, whole.
  RgbImage picture() const {
    RgbImage image;
    image.width = width_;
    image.height = height_;
    image.rgb.resize(shown_.size() * 3);
    for (size_t i = 0; i < shown_.size(); ++i) {
      image.rgb[i * 3] = static_cast<uint8_t>(shown_[i] >> 16);
      image.rgb[i * 3 + 1] = static_cast<uint8_t>(shown_[i] >> 8);
      image.rgb[i * 3 + 2] = static_cast<uint8_t>(shown_[i]);
    }
    return image;
  }

 private:
  FrameChange compose(const RobotImage& image, uint32_t robotRgb) {
    std::vector<uint32_t> robot;
    image.rasterize(scale_, width_, height_, [&](int x, int y) {
      robot.push_back(static_cast<uint32_t>(y) * static_cast<uint32_t>(width_) + static_cast<uint32_t>(x));
    });
    FrameChange change;
    if (shown_.empty()) {  // the first picture: all of it
      const size_t area = static_cast<size_t>(width_) * static_cast<size_t>(height_);
      shown_.resize(area);
      for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) shown_[index(x, y)] = screenRgb(x, y);
      for (uint32_t q : robot) shown_[q] = robotRgb;
      changed_.assign(area, 0);
      for (uint32_t p : touched_) mark_[p] = 0;
      touched_.clear();
      robot_ = std::move(robot);
      change.width = width_;
      change.height = height_;
      change.whole = &shown_;
      return change;
    }
    // Where the picture may have changed (the screen's changed pixels, where the robot was and
    // where it is), what it is now: the robot (rasterize gives its pixels in order) or else the
    // screen.
    PixelBox box;
    auto compare = [&](uint32_t q) {
      const int x = static_cast<int>(q % static_cast<uint32_t>(width_)), y = static_cast<int>(q / static_cast<uint32_t>(width_));
      const uint32_t now = std::binary_search(robot.begin(), robot.end(), q) ? robotRgb : screenRgb(x, y);
      if (now == shown_[q]) return;
      shown_[q] = now;
      changed_[q] = 1;
      box.add(x, y);
    };
    for (uint32_t p : touched_) {
      mark_[p] = 0;
      const int sx = static_cast<int>(p % kW) * scale_, sy = static_cast<int>(p / kW) * scale_;
      for (int y = sy; y < sy + scale_; ++y)
        for (int x = sx; x < sx + scale_; ++x) compare(static_cast<uint32_t>(index(x, y)));
    }
    touched_.clear();
    for (uint32_t q : robot_) compare(q);
    for (uint32_t q : robot) compare(q);
    robot_ = std::move(robot);
    if (box.empty()) return change;
    change.x = box.x0;
    change.y = box.y0;
    change.width = box.x1 - box.x0 + 1;
    change.height = box.y1 - box.y0 + 1;
    const size_t area = static_cast<size_t>(change.width) * static_cast<size_t>(change.height);
    change.rgb.resize(area);
    change.changed.resize(area);
    for (int y = 0; y < change.height; ++y) {
      const size_t from = index(box.x0, box.y0 + y), at = static_cast<size_t>(y) * static_cast<size_t>(change.width);
      std::copy_n(shown_.begin() + static_cast<long>(from), change.width, change.rgb.begin() + static_cast<long>(at));
      std::copy_n(changed_.begin() + static_cast<long>(from), change.width, change.changed.begin() + static_cast<long>(at));
      std::fill_n(changed_.begin() + static_cast<long>(from), change.width, uint8_t{0});
    }
    return change;
  }

  size_t index(int x, int y) const { return static_cast<size_t>(y) * static_cast<size_t>(width_) + static_cast<size_t>(x); }
  uint32_t screenRgb(int x, int y) const {
    const Colour c = screen_[static_cast<size_t>(y / scale_) * kW + static_cast<size_t>(x / scale_)];
    if (c != lastColour_) {
      lastColour_ = c;
      lastRgb_ = colourToRgb(c);
    }
    return lastRgb_;
  }

  /// Brings the screen to keyframe `frame`, noting the pixels that change.
  void advance(uint32_t frame) {
    if (screen_.empty()) {
      screen_.assign(kPixels, colours::kWhite);  // as Recording::screen starts
      mark_.assign(kPixels, 0);
    }
    const std::vector<RecordedFrame>& frames = rec_.frames();
    if (frames.empty()) return;
    frame = std::min<uint32_t>(frame, static_cast<uint32_t>(frames.size() - 1));
    if (applied_ >= 0 && frame < static_cast<uint32_t>(applied_)) {  // steps go forward; be safe
      const std::vector<Colour> now = rec_.screen(frame);
      for (size_t p = 0; p < kPixels; ++p) set(p, now[p]);
      applied_ = frame;
      return;
    }
    for (size_t f = static_cast<size_t>(applied_ + 1); f <= frame; ++f) {
      size_t at = 0;
      for (const ScreenRun& r : frames[f].runs) {
        const size_t n = std::min<size_t>(r.count, kPixels - at);
        if (r.colour != kSameColour)
          for (size_t p = at; p < at + n; ++p) set(p, r.colour);
        at += n;
      }
    }
    applied_ = frame;
  }
  void set(size_t p, Colour c) {
    if (screen_[p] == c) return;
    screen_[p] = c;
    if (!mark_[p]) {
      mark_[p] = 1;
      touched_.push_back(static_cast<uint32_t>(p));
    }
  }

  const Recording& rec_;
  int scale_, width_, height_;
  std::vector<Colour> screen_;     ///< the screen of keyframe applied_ (colour numbers)
  long applied_ = -1;
  std::vector<uint8_t> mark_;      ///< screen pixels changed since the last moveTo
  std::vector<uint32_t> touched_;  ///< ... and their list
  std::vector<uint32_t> shown_;    ///< the picture last given (0xRRGGBB); empty before the first
  std::vector<uint8_t> changed_;   ///< image pixels that changed (cleared as they are given)
  std::vector<uint32_t> robot_;    ///< the image pixels the robot covers in shown_
  mutable Colour lastColour_ = kSameColour;
  mutable uint32_t lastRgb_ = 0;
};

/// A GIF's delay in hundredths of a second: at least 2 (browsers slow shorter delays down to
/// 10), at most what the field holds.
int gifDelay(long centis) { return static_cast<int>(std::clamp<long>(centis, 2, 65535)); }

std::string base64(const uint8_t* data, size_t size) {
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((size + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < size; i += 3) {
    const uint32_t v = static_cast<uint32_t>(data[i]) << 16 | static_cast<uint32_t>(data[i + 1]) << 8 | data[i + 2];
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += kDigits[v & 63];
  }
  if (i < size) {
    uint32_t v = static_cast<uint32_t>(data[i]) << 16;
    if (i + 1 < size) v |= static_cast<uint32_t>(data[i + 1]) << 8;
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < size ? kDigits[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

// ---------------------------------------------------------------- GIF

/// The GIF's one colour map: the 16 RobotBASIC colours first (indices 0..15), then the other
/// colours the run shows, most pixels first, up to 255 in all; the next index is transparent
/// (a frame's pixels that did not change). A colour beyond the 255 shows as the nearest one.
class GifColours {
 public:
  explicit GifColours(const Recording& rec) {
    std::unordered_map<uint32_t, uint64_t> weight;
    for (const RecordedFrame& f : rec.frames())
      for (const ScreenRun& r : f.runs)
        if (r.colour != kSameColour) weight[colourToRgb(r.colour)] += r.count;
    for (const RecordedStep& s : rec.steps())
      if (s.located) weight[colourToRgb(s.robotColour)] += uint64_t{1} << 40;  // the robot always fits
    for (Colour c = 0; c < 16; ++c) add(colourToRgb(c));
    std::vector<std::pair<uint64_t, uint32_t>> others;
    for (const auto& [rgb, w] : weight)
      if (!index_.count(rgb)) others.push_back({w, rgb});
    std::sort(others.begin(), others.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    for (const auto& [w, rgb] : others) {
      if (rgb_.size() >= 255) break;
      add(rgb);
    }
    transparent_ = static_cast<uint8_t>(rgb_.size());
    size_ = 2;
    while (size_ < static_cast<int>(rgb_.size()) + 1) size_ *= 2;
  }

  uint8_t transparent() const { return transparent_; }
  int size() const { return size_; }
  /// The map giflib writes (unused entries black).
  std::vector<GifColorType> map() const {
    std::vector<GifColorType> out(static_cast<size_t>(size_), GifColorType{0, 0, 0});
    for (size_t i = 0; i < rgb_.size(); ++i)
      out[i] = {static_cast<GifByteType>(rgb_[i] >> 16), static_cast<GifByteType>(rgb_[i] >> 8), static_cast<GifByteType>(rgb_[i])};
    return out;
  }
  uint8_t of(uint32_t rgb) {
    if (rgb == lastRgb_) return lastIndex_;
    auto it = index_.find(rgb);
    uint8_t i = it != index_.end() ? it->second : nearest(rgb);
    lastRgb_ = rgb;
    lastIndex_ = i;
    return i;
  }

 private:
  void add(uint32_t rgb) {
    index_.emplace(rgb, static_cast<uint8_t>(rgb_.size()));
    rgb_.push_back(rgb);
  }
  uint8_t nearest(uint32_t rgb) {
    auto channel = [](uint32_t c, int shift) { return static_cast<int>((c >> shift) & 255); };
    long best = std::numeric_limits<long>::max();
    uint8_t at = 0;
    for (size_t i = 0; i < rgb_.size(); ++i) {
      long d = 0;
      for (int shift : {16, 8, 0}) {
        const long e = channel(rgb, shift) - channel(rgb_[i], shift);
        d += e * e;
      }
      if (d < best) {
        best = d;
        at = static_cast<uint8_t>(i);
      }
    }
    index_.emplace(rgb, at);  // remembered: the next time is a lookup
    return at;
  }

  std::vector<uint32_t> rgb_;
  std::unordered_map<uint32_t, uint8_t> index_;
  uint8_t transparent_ = 0;
  int size_ = 32;
  uint32_t lastRgb_ = 0xFFFFFFFFu;
  uint8_t lastIndex_ = 0;
};

int appendBytes(GifFileType* gif, const GifByteType* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(gif->UserData);
  out->insert(out->end(), data, data + size);
  return size;
}

/// giflib writing into memory; throws std::runtime_error naming giflib's error.
class GifWriter {
 public:
  GifWriter() {
    int error = 0;
    gif_ = EGifOpen(&bytes_, appendBytes, &error);
    if (!gif_) fail(error);
  }
  ~GifWriter() {
    if (gif_) EGifCloseFile(gif_, nullptr);
  }
  GifWriter(const GifWriter&) = delete;
  GifWriter& operator=(const GifWriter&) = delete;

  GifFileType* gif() { return gif_; }
  size_t size() const { return bytes_.size(); }
  /// Sets the delay (hundredths of a second) of a frame already written, at `at`.
  void setDelay(size_t at, int centis) {
    bytes_.at(at) = static_cast<uint8_t>(centis & 255);
    bytes_.at(at + 1) = static_cast<uint8_t>(centis >> 8);
  }
  void check(int result) {
    if (result == GIF_ERROR) fail(gif_->Error);
  }
  std::vector<uint8_t> finish() {
    int error = 0;
    GifFileType* gif = gif_;
    gif_ = nullptr;
    if (EGifCloseFile(gif, &error) == GIF_ERROR) fail(error);
    return std::move(bytes_);
  }

 private:
  [[noreturn]] static void fail(int error) {
    const char* why = GifErrorString(error);
    throw std::runtime_error(std::string("giflib: ") + (why ? why : "failed"));
  }
  std::vector<uint8_t> bytes_;
  GifFileType* gif_ = nullptr;
};

/// Writes a frame with a delay to be set later (setDelay) and returns where that delay is.
size_t putGifFrame(GifWriter& w, GifColours& colours, const FrameChange& c, bool first) {
  GraphicsControlBlock gcb{};
  gcb.DisposalMode = DISPOSE_DO_NOT;  // the next frame draws over this one
  gcb.UserInputFlag = false;
  gcb.DelayTime = 0;
  gcb.TransparentColor = first ? NO_TRANSPARENT_COLOR : colours.transparent();
  GifByteType ext[4];
  EGifGCBToExtension(&gcb, ext);
  // giflib writes at once: the extension is 21 F9 04, the packed byte, then the delay.
  const size_t delayAt = w.size() + 4;
  w.check(EGifPutExtension(w.gif(), GRAPHICS_EXT_FUNC_CODE, 4, ext));
  w.check(EGifPutImageDesc(w.gif(), c.x, c.y, c.width, c.height, false, nullptr));
  std::vector<GifPixelType> line(static_cast<size_t>(c.width));
  for (int y = 0; y < c.height; ++y) {
    const size_t at = static_cast<size_t>(y) * static_cast<size_t>(c.width);
    for (int x = 0; x < c.width; ++x) {
      const size_t i = at + static_cast<size_t>(x);
      line[static_cast<size_t>(x)] = c.changedAt(i) ? colours.of(c.pixel(i)) : colours.transparent();
    }
    w.check(EGifPutLine(w.gif(), line.data(), c.width));
  }
  return delayAt;
}

}  // namespace

RgbImage glideImage(const Recording& recording, size_t step, uint32_t part, uint32_t parts, int scale) {
  const size_t count = recording.steps().size();
  if (step >= count) throw std::out_of_range("glideImage: no such step");
  if (part == 0 || parts == 0) return frameImage(recording, step, scale);
  if (part >= parts && step + 1 < count) return frameImage(recording, step + 1, scale);
  Composer composer(recording, scale);
  composer.moveTo(step);
  composer.glideTo(step, part, parts);
  return composer.picture();
}

std::vector<uint8_t> encodeGif(const Recording& recording, const AnimationOptions& options) {
  if (recording.steps().empty()) throw std::runtime_error("the recording holds no step");
  const FrameTimes times = animationTimes(recording, options);
  GifColours colours(recording);
  Composer composer(recording, options.scale);
  GifWriter w;
  EGifSetGifVersion(w.gif(), true);
  {
    const std::vector<GifColorType> map = colours.map();
    ColorMapObject* object = GifMakeMapObject(colours.size(), map.data());
    if (!object) throw std::runtime_error("giflib: out of memory");
    const int result = EGifPutScreenDesc(w.gif(), composer.width(), composer.height(), 8, colours::kWhite, object);
    GifFreeMapObject(object);
    w.check(result);
  }
  // NETSCAPE2.0: loop for ever.
  w.check(EGifPutExtensionLeader(w.gif(), APPLICATION_EXT_FUNC_CODE));
  w.check(EGifPutExtensionBlock(w.gif(), 11, "NETSCAPE2.0"));
  const GifByteType loop[3] = {1, 0, 0};
  w.check(EGifPutExtensionBlock(w.gif(), 3, loop));
  w.check(EGifPutExtensionTrailer(w.gif()));

  // Each frame's delay is set once the next frame's time is known. A frame that would show for
  // less than 2/100 s is skipped: its changes come with the next frame, and the times stay.
  std::optional<size_t> delayAt;  // of the frame written last
  long shownFrom = 0;             // ... and its time
  const size_t count = times.steps.size();
  for (size_t k = 0; k < count; ++k) {
    long start = std::lround(times.seconds[k] * 100);
    const bool last = k + 1 == count;
    if (delayAt && start - shownFrom < 2) {
      if (!last) continue;
      start = shownFrom + 2;
    }
    const FrameChange change = times.part[k] ? composer.glideTo(times.steps[k], times.part[k], times.parts[k])
                                             : composer.moveTo(times.steps[k]);
    if (delayAt && change.width == 0) continue;  // nothing new shows: the frame before lasts
    if (delayAt) w.setDelay(*delayAt, gifDelay(start - shownFrom));
    delayAt = putGifFrame(w, colours, change, !delayAt);
    shownFrom = start;
  }
  if (delayAt) w.setDelay(*delayAt, gifDelay(std::lround(std::clamp(options.hold, 0.0, kMaxHold) * 100)));
  return w.finish();
}

// ---------------------------------------------------------------- SVG

namespace {

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", s);
  std::string out = buf;
  while (out.back() == '0') out.pop_back();
  if (out.back() == '.') out.pop_back();
  return out;
}

/// A frame's image as a data: URI of a PNG. In palette colours with the pixels that did not
/// change transparent (they show what is under them, as in the GIF), which compresses a thin
/// trail across a large box to little; a box of more than 255 colours is written whole, in RGB.
std::string pngDataUri(const FrameChange& c) {
  const size_t area = c.area();
  std::vector<uint8_t> indices(area);
  std::vector<uint8_t> map = {0, 0, 0, 0};  // index 0: transparent
  std::unordered_map<uint32_t, uint8_t> index;
  bool fits = true;
  uint32_t lastRgb = 0;
  uint8_t last = 0;
  for (size_t i = 0; i < area && fits; ++i) {
    if (!c.changedAt(i)) continue;
    const uint32_t rgb = c.pixel(i);
    if (last == 0 || rgb != lastRgb) {
      auto it = index.find(rgb);
      if (it == index.end()) {
        if (index.size() == 255) {
          fits = false;
          break;
        }
        it = index.emplace(rgb, static_cast<uint8_t>(index.size() + 1)).first;
        map.insert(map.end(), {static_cast<uint8_t>(rgb >> 16), static_cast<uint8_t>(rgb >> 8), static_cast<uint8_t>(rgb), 255});
      }
      last = it->second;
      lastRgb = rgb;
    }
    indices[i] = last;
  }
  std::vector<uint8_t> png;
  if (fits) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(c.width);
    image.height = static_cast<png_uint_32>(c.height);
    image.format = PNG_FORMAT_RGBA_COLORMAP;
    image.colormap_entries = static_cast<png_uint_32>(map.size() / 4);
    png_alloc_size_t size = 0;
    // The first call measures, the second writes.
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, indices.data(), 0, map.data()))
      throw std::runtime_error(std::string("cannot encode PNG: ") + image.message);
    png.resize(size);
    if (!png_image_write_to_memory(&image, png.data(), &size, 0, indices.data(), 0, map.data()))
      throw std::runtime_error(std::string("cannot encode PNG: ") + image.message);
    png.resize(size);
  } else {
    RgbImage image;
    image.width = c.width;
    image.height = c.height;
    image.rgb.resize(area * 3);
    for (size_t i = 0; i < area; ++i) {
      const uint32_t rgb = c.pixel(i);
      image.rgb[i * 3] = static_cast<uint8_t>(rgb >> 16);
      image.rgb[i * 3 + 1] = static_cast<uint8_t>(rgb >> 8);
      image.rgb[i * 3 + 2] = static_cast<uint8_t>(rgb);
    }
    png = encodePng(image);
  }
  return "data:image/png;base64," + base64(png.data(), png.size());
}

std::string svgImage(const FrameChange& c, const std::string& attributes) {
  return "<image" + attributes + " x=\"" + std::to_string(c.x) + "\" y=\"" + std::to_string(c.y) + "\" width=\"" + std::to_string(c.width) +
         "\" height=\"" + std::to_string(c.height) + "\" xlink:href=\"" + pngDataUri(c) + "\"/>";
}

}  // namespace

std::string animatedSvg(const Recording& recording, const AnimationOptions& options) {
  if (recording.steps().empty()) throw std::runtime_error("the recording holds no step");
  const FrameTimes times = animationTimes(recording, options);
  Composer composer(recording, options.scale);
  const std::string w = std::to_string(composer.width()), h = std::to_string(composer.height());
  std::string body;
  size_t shown = 0;
  double end = 0;
  for (size_t k = 0; k < times.steps.size(); ++k) {
    const FrameChange c = times.part[k] ? composer.glideTo(times.steps[k], times.part[k], times.parts[k])
                                        : composer.moveTo(times.steps[k]);
    if (c.width == 0) continue;
    // Each image after the first appears at its frame's time and stays.
    body += svgImage(c, shown == 0 ? "" : " class=\"f\" style=\"animation-delay:" + seconds(times.seconds[k]) + "s\"");
    body += "\n";
    ++shown;
    end = times.seconds[k];
  }
  std::string svg =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" + w +
      "\" height=\"" + h + "\" viewBox=\"0 0 " + w + " " + h + "\">\n"
      "<!-- A replay written by rb render: " + std::to_string(shown) + " frames in " + seconds(end) +
      " s. The first image is the whole screen; each one after it is the box that changed (the pixels that did "
      "not, transparent), shown from its animation-delay on and kept, so the last frame stays. -->\n"
      "<style>image{image-rendering:optimizeSpeed;image-rendering:pixelated}"
      ".f{visibility:hidden;animation:rb-show 0s forwards}"
      "@keyframes rb-show{to{visibility:visible}}</style>\n";
  svg += body;
  svg += "</svg>\n";
  return svg;
}

// ---------------------------------------------------------------- HTML player

namespace {

/// Little-endian varints and friends, read back by the page's Reader.
class Packer {
 public:
  void u(uint64_t v) {
    while (v >= 128) {
      bytes_.push_back(static_cast<char>((v & 127) | 128));
      v >>= 7;
    }
    bytes_.push_back(static_cast<char>(v));
  }
  void z(int64_t v) { u(v < 0 ? (static_cast<uint64_t>(-(v + 1)) << 1) | 1 : static_cast<uint64_t>(v) << 1); }
  void f64(double d) {
    unsigned char b[8];
    std::memcpy(b, &d, 8);  // x86-64 and aarch64 Linux: little-endian, as the page reads it
    bytes_.append(reinterpret_cast<const char*>(b), 8);
  }
  void raw(std::string_view s) { bytes_.append(s); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

std::vector<uint8_t> deflateBytes(const std::string& in) {
  uLongf size = compressBound(static_cast<uLong>(in.size()));
  std::vector<uint8_t> out(size);
  if (compress2(out.data(), &size, reinterpret_cast<const Bytef*>(in.data()), static_cast<uLong>(in.size()), Z_DEFAULT_COMPRESSION) != Z_OK)
    throw std::runtime_error("zlib: cannot compress the player's data");
  out.resize(size);
  return out;
}


std::string jsonNumber(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// The page's robot (the function robotPixels in the player's script does the same, operation
/// for operation).
struct PlayerRobot {
  bool visible = false;
  double cx = 0, cy = 0, r = 0, dx = 0, dy = 0;

  explicit PlayerRobot(const QuantizedPose& q)
      : visible(q.visible),
        cx(static_cast<double>(q.x) / kPosQ),
        cy(static_cast<double>(q.y) / kPosQ),
        r(static_cast<double>(q.r) / kPosQ),
        dx(static_cast<double>(q.dx) / kDirQ),
        dy(static_cast<double>(q.dy) / kDirQ) {}

  bool covers(double u, double v) const {
    const double x = u - cx, y = v - cy;
    const double d2 = x * x + y * y;
    if (d2 > r * r) return false;
    const double inner = r - 3;
    if (inner < 0 || d2 > inner * inner) return true;
    double t = x * dx + y * dy;
    t = t < 0 ? 0 : t > r ? r : t;
    const double ex = x - t * dx, ey = y - t * dy;
    return ex * ex + ey * ey < 2.25;
  }

  /// The screen pixels (y * 800 + x) it covers, ascending.
  std::vector<uint32_t> pixels() const {
    std::vector<uint32_t> out;
    if (!visible) return out;
    const double x0 = std::max(0.0, std::floor(cx - r) - 2), x1 = std::min(static_cast<double>(kW - 1), std::ceil(cx + r) + 2);
    const double y0 = std::max(0.0, std::floor(cy - r) - 2), y1 = std::min(static_cast<double>(kH - 1), std::ceil(cy + r) + 2);
    for (double v = y0; v <= y1; ++v)
      for (double u = x0; u <= x1; ++u)
        if (covers(u, v)) out.push_back(static_cast<uint32_t>(v) * kW + static_cast<uint32_t>(u));
    return out;
  }
};

/// The pixels where the page's robot differs from rb render's (robot_image.h, at scale 1).
std::vector<uint32_t> robotCorrections(const RecordedStep& s, const QuantizedPose& q) {
  std::vector<uint32_t> exact;
  RobotImage(robotOf(s)).rasterize(1, kW, kH, [&](int x, int y) {
    exact.push_back(static_cast<uint32_t>(y) * kW + static_cast<uint32_t>(x));
  });
  const std::vector<uint32_t> page = PlayerRobot(q).pixels();
  std::vector<uint32_t> differ;
  std::set_symmetric_difference(exact.begin(), exact.end(), page.begin(), page.end(), std::back_inserter(differ));
  return differ;
}

/// robotCorrections() remembered by its inputs, the robot's drawn state (placed, centre,
/// heading, radius: its colour changes no pixel) and the quantized pose: a program that goes
/// round the same path (a loop of 100,000 steps) draws a few poses again and again, each
/// rasterized twice for nothing. At most kMaxPoses poses are kept (then it starts afresh).
class CorrectionCache {
 public:
  const std::vector<uint32_t>& get(const RecordedStep& s, const QuantizedPose& q) {
    const Key key = keyOf(s, q);
    auto it = map_.find(key);
    if (it != map_.end()) return it->second;
    if (map_.size() >= kMaxPoses) map_.clear();
    return map_.emplace(key, robotCorrections(s, q)).first->second;
  }

 private:
  static constexpr size_t kMaxPoses = 1 << 16;
  struct Key {
    uint64_t pose[4];  ///< x, y, heading, radius, bit for bit (a NaN is itself)
    int64_t quantized[6];
    bool located, visible;
    friend bool operator==(const Key&, const Key&) = default;
  };
  struct Hash {
    size_t operator()(const Key& k) const {
      uint64_t h = k.located | uint64_t{k.visible} << 1;
      auto mix = [&h](uint64_t v) {
        h ^= v + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h *= 0xbf58476d1ce4e5b9ull;
      };
      for (uint64_t v : k.pose) mix(v);
      for (int64_t v : k.quantized) mix(static_cast<uint64_t>(v));
      return static_cast<size_t>(h ^ (h >> 31));
    }
  };
  static Key keyOf(const RecordedStep& s, const QuantizedPose& q) {
    Key k{};
    const double pose[4] = {s.x, s.y, s.heading, s.radius};
    std::memcpy(k.pose, pose, sizeof pose);
    const int64_t quantized[6] = {q.x, q.y, q.r, q.dx, q.dy, q.heading};
    std::memcpy(k.quantized, quantized, sizeof quantized);
    k.located = s.located;
    k.visible = q.visible;
    return k;
  }
  std::unordered_map<Key, std::vector<uint32_t>, Hash> map_;
};

const char* statusName(RunStatus s) {
  switch (s) {
    case RunStatus::Finished: return "finished";
    case RunStatus::RuntimeError: return "runtime error";
    case RunStatus::StepLimit: return "step limit";
    case RunStatus::Timeout: return "timeout";
    case RunStatus::Stopped: return "stopped";
  }
  return "finished";
}

extern const char kPlayerStyle[];
extern const char kPlayerScript[];

}  // namespace

std::string htmlPlayer(const Recording& recording, const PlayerSource& source, const AnimationOptions& options) {
  const std::vector<RecordedStep>& steps = recording.steps();
  if (steps.empty()) throw std::runtime_error("the recording holds no step");
  const std::vector<RecordedFrame>& frames = recording.frames();

  // Colour numbers as indices into the page's palette (white always there: the start).
  std::unordered_map<Colour, uint32_t> colourIndex;
  std::vector<uint32_t> palette;
  auto indexOf = [&](Colour c) {
    auto [it, added] = colourIndex.emplace(c, static_cast<uint32_t>(palette.size()));
    if (added) palette.push_back(colourToRgb(c));
    return it->second;
  };
  const uint32_t white = indexOf(colours::kWhite);

  Packer p;
  // The keyframes: the first whole, every other one as what changed since the one before (the
  // recording's whole frames, there to make its own seeking quick, would be most of the page;
  // the page keeps screens of its own to seek).
  size_t runs = 0;
  {
    // Screens in large memory (one huge page each where there are some, not 470 page faults).
    Pixels screen(kPixels, colours::kWhite), now;
    std::vector<ScreenRun> changes;
    for (size_t k = 0; k < frames.size(); ++k) {
      const RecordedFrame& f = frames[k];
      const std::vector<ScreenRun>* list = &f.runs;
      if (k > 0 && f.full) {
        now.clear();
        for (const ScreenRun& r : f.runs) now.insert(now.end(), std::min<size_t>(r.count, kPixels - now.size()), r.colour);
        now.resize(kPixels, colours::kWhite);
        changes.clear();
        for (size_t i = 0; i < kPixels;) {
          size_t j = i;
          if (now[i] == screen[i]) {
            while (j < kPixels && now[j] == screen[j]) ++j;
            changes.push_back({static_cast<uint32_t>(j - i), kSameColour});
          } else {
            while (j < kPixels && now[j] == now[i] && now[j] != screen[j]) ++j;
            changes.push_back({static_cast<uint32_t>(j - i), now[i]});
          }
          i = j;
        }
        screen.swap(now);
        list = &changes;
      } else {
        size_t at = 0;
        for (const ScreenRun& r : f.runs) {
          const size_t len = std::min<size_t>(r.count, kPixels - at);
          if (r.colour != kSameColour) std::fill_n(screen.begin() + static_cast<long>(at), len, r.colour);
          at += len;
        }
      }
      p.u(list->size());
      for (const ScreenRun& r : *list) {
        p.u(r.count);
        p.u(r.colour == kSameColour ? 0 : indexOf(r.colour) + 1);
      }
      runs += list->size();
    }
  }

  // The steps, a column at a time (each as differences from the step before: they compress).
  const size_t n = steps.size();
  std::vector<QuantizedPose> poses(n);
  for (size_t i = 0; i < n; ++i) poses[i] = quantizePose(steps[i]);
  auto column = [&](auto value, bool zigzag) {
    int64_t before = 0;
    for (size_t i = 0; i < n; ++i) {
      const int64_t v = value(i);
      if (zigzag) p.z(v - before);
      else p.u(static_cast<uint64_t>(v - before));
      before = v;
    }
  };
  column([&](size_t i) { return static_cast<int64_t>(steps[i].step); }, false);
  column([&](size_t i) { return static_cast<int64_t>(steps[i].loc.file); }, true);
  column([&](size_t i) { return static_cast<int64_t>(steps[i].loc.line); }, true);
  column([&](size_t i) { return static_cast<int64_t>(steps[i].frame); }, true);
  column([&](size_t i) { return static_cast<int64_t>(steps[i].output); }, true);
  // Flags: 1 placed, 2 pen down, 4 the robot is drawn, 8 the pose differs from the step before.
  std::vector<bool> poseChanged(n);
  for (size_t i = 0; i < n; ++i) {
    const RecordedStep& s = steps[i];
    poseChanged[i] = i == 0 || s.located != steps[i - 1].located || s.x != steps[i - 1].x ||
                     s.y != steps[i - 1].y || s.heading != steps[i - 1].heading || s.radius != steps[i - 1].radius;
    p.u((s.located ? 1u : 0u) | (s.pen ? 2u : 0u) | (poses[i].visible ? 4u : 0u) | (poseChanged[i] ? 8u : 0u));
  }
  column([&](size_t i) { return poses[i].x; }, true);
  column([&](size_t i) { return poses[i].y; }, true);
  column([&](size_t i) { return poses[i].dx; }, true);
  column([&](size_t i) { return poses[i].dy; }, true);
  column([&](size_t i) { return poses[i].r; }, true);
  column([&](size_t i) { return poses[i].heading; }, true);
  column([&](size_t i) { return static_cast<int64_t>(indexOf(steps[i].robotColour)); }, true);

  // The robot's corrections, for each step where the pose changed.
  size_t corrections = 0;
  {
    Packer c;
    CorrectionCache cache;
    size_t before = 0;
    for (size_t i = 0; i < n; ++i) {
      if (!poseChanged[i] || (!steps[i].located)) continue;
      const std::vector<uint32_t>& differ = cache.get(steps[i], poses[i]);
      if (differ.empty()) continue;
      c.u(i - before);
      before = i;
      c.u(differ.size());
      int64_t last = 0;
      for (uint32_t px : differ) {
        c.z(static_cast<int64_t>(px) - last);
        last = px;
      }
      ++corrections;
    }
    p.raw(c.bytes());
  }

  // Sensor readings; input lines go in the JSON.
  std::vector<std::string> sensorNames;
  std::unordered_map<std::string, uint32_t> sensorIndex;
  size_t sensors = 0;
  std::string inputs = "[";
  {
    Packer e;
    uint64_t before = 0;
    for (const RecordedEvent& ev : recording.events()) {
      if (ev.kind == RecordedEvent::Input) {
        if (inputs.size() > 1) inputs += ',';
        inputs += "[" + std::to_string(ev.step) + ",";
        appendJsonString(inputs, ev.what);
        inputs += "]";
        continue;
      }
      auto [it, added] = sensorIndex.emplace(ev.what, static_cast<uint32_t>(sensorNames.size()));
      if (added) sensorNames.push_back(ev.what);
      e.u(ev.step - std::min(before, ev.step));
      before = ev.step;
      e.u(it->second);
      const double v = ev.value;
      if (std::isfinite(v) && v == std::trunc(v) && std::fabs(v) < 1e15) {
        e.u(0);
        e.z(static_cast<int64_t>(v));
      } else {
        e.u(1);
        e.f64(v);
      }
      ++sensors;
    }
    p.raw(e.bytes());
  }
  inputs += "]";

  // What plays: the animation's frames and their times (ms).
  const FrameTimes times = animationTimes(recording, options);
  {
    size_t before = 0;
    int64_t ms = 0;
    for (size_t k = 0; k < times.steps.size(); ++k) {
      p.u(times.steps[k] - before);
      before = times.steps[k];
      const int64_t at = std::llround(times.seconds[k] * 1000);
      p.u(static_cast<uint64_t>(std::max<int64_t>(0, at - ms)));
      ms = std::max(ms, at);
      // A glide's part of the way to the next step (0: the step itself), then its parts.
      p.u(times.part[k]);
      if (times.part[k]) p.u(times.parts[k]);
    }
  }
  p.u(recording.output().size());
  p.raw(recording.output());

  std::string meta = "{\"name\":";
  appendJsonString(meta, source.name);
  meta += ",\"source\":";
  appendJsonString(meta, source.text);
  meta += ",\"file\":" + std::to_string(source.file);
  meta += ",\"width\":" + std::to_string(kW) + ",\"height\":" + std::to_string(kH);
  meta += ",\"scale\":" + std::to_string(std::clamp(options.scale, 1, kMaxScale));
  meta += ",\"posQ\":" + jsonNumber(kPosQ) + ",\"dirQ\":" + jsonNumber(kDirQ);
  meta += ",\"steps\":" + std::to_string(n) + ",\"frames\":" + std::to_string(frames.size());
  meta += ",\"runs\":" + std::to_string(runs) + ",\"corrections\":" + std::to_string(corrections);
  meta += ",\"sensors\":" + std::to_string(sensors) + ",\"play\":" + std::to_string(times.steps.size());
  meta += ",\"white\":" + std::to_string(white);
  meta += std::string(",\"autoplay\":") + (options.autoplay ? "true" : "false");
  meta += ",\"palette\":[";
  for (size_t i = 0; i < palette.size(); ++i) {
    if (i) meta += ',';
    meta += std::to_string(palette[i]);
  }
  meta += "],\"sensorNames\":[";
  for (size_t i = 0; i < sensorNames.size(); ++i) {
    if (i) meta += ',';
    appendJsonString(meta, sensorNames[i]);
  }
  meta += "],\"inputs\":" + inputs;
  meta += ",\"totalSteps\":" + std::to_string(recording.totalSteps());
  meta += ",\"stride\":" + std::to_string(recording.stepStride());
  meta += ",\"outputBytes\":" + std::to_string(recording.outputBytes());
  meta += ",\"status\":\"" + std::string(statusName(recording.status())) + "\"";
  meta += ",\"error\":";
  if (recording.error() && recording.status() != RunStatus::Finished) {
    const Diagnostic& d = *recording.error();
    meta += "{\"file\":" + std::to_string(d.loc.file) + ",\"line\":" + std::to_string(d.loc.line) +
            ",\"col\":" + std::to_string(d.loc.col) + ",\"message\":";
    appendJsonString(meta, d.message);
    meta += "}";
  } else {
    meta += "null";
  }
  meta += "}";

  const std::vector<uint8_t> packed = deflateBytes(p.bytes());
  std::string title;
  {
    for (char c : source.name) {
      switch (c) {
        case '<': title += "&lt;"; break;
        case '>': title += "&gt;"; break;
        case '&': title += "&amp;"; break;
        case '"': title += "&quot;"; break;
        default: title += c;
      }
    }
  }
  std::string html;
  html.reserve(packed.size() * 4 / 3 + meta.size() + 32768);
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta name=\"generator\" content=\"rb render --animate\">\n";
  html += "<link rel=\"icon\" href=\"data:,\">\n";
  html += "<title>" + title + " \xE2\x80\x94 rb replay</title>\n<style>";
  html += kPlayerStyle;
  html += "</style>\n</head>\n<body>\n";
  html +=
      "<header><h1 id=\"title\"></h1><span id=\"ending\"></span></header>\n"
      "<main>\n<section id=\"stage\" aria-label=\"the replay\">\n"
      "<canvas id=\"screen\" width=\"800\" height=\"600\" role=\"img\" aria-label=\"the screen\" "
      "aria-describedby=\"describe\"></canvas>\n"
      "<div id=\"controls\">"
      "<button id=\"back\" title=\"one recorded step back (Left)\" aria-keyshortcuts=\"ArrowLeft\">"
      "<span aria-hidden=\"true\">&#x25C0; </span>step back</button>"
      "<button id=\"play\" title=\"play or pause (Space)\" aria-keyshortcuts=\"Space\">"
      "<span aria-hidden=\"true\">&#x25B6; </span>play</button>"
      "<button id=\"forward\" title=\"one recorded step forward (Right)\" aria-keyshortcuts=\"ArrowRight\">"
      "step on<span aria-hidden=\"true\"> &#x25B6;</span></button>"
      "<input id=\"timeline\" type=\"range\" min=\"0\" max=\"0\" value=\"0\" aria-label=\"timeline\">"
      "<label>speed <select id=\"speed\"><option>0.25</option><option>0.5</option><option selected>1</option>"
      "<option>2</option><option>4</option><option>8</option><option>16</option></select></label>"
      "<label title=\"start playing when the replay opens (remembered on this computer)\">"
      "<input id=\"autoplay\" type=\"checkbox\"> play on opening</label>"
      "</div>\n<div id=\"position\"></div>\n"
      "<p id=\"keys\">Keys: Space plays or pauses; Left and Right step back and on; Home and End go to the first "
      "and the last step.</p>\n<div id=\"banner\" hidden></div>\n"
      "<div id=\"describe\" class=\"sr-only\" aria-live=\"polite\" aria-atomic=\"true\"></div>\n"
      "<div id=\"alert\" class=\"sr-only\" role=\"alert\"></div>\n</section>\n"
      "<aside>\n<h2>Robot</h2><div id=\"pose\"></div>\n"
      "<h2>Sensors last read</h2><table id=\"sensors\"></table>\n"
      "<h2 id=\"source-h\">Source</h2><div id=\"source\" class=\"pane\" tabindex=\"0\" role=\"region\" "
      "aria-labelledby=\"source-h\"></div>\n"
      "<h2 id=\"output-h\">Output</h2><pre id=\"output\" class=\"pane\" tabindex=\"0\" role=\"region\" "
      "aria-labelledby=\"output-h\"></pre>\n<div id=\"inputs\"></div>\n</aside>\n</main>\n"
      "<noscript>The replay needs JavaScript.</noscript>\n";
  html += "<script type=\"application/json\" id=\"rb-meta\">" + meta + "</script>\n";
  html += "<script type=\"application/octet-stream\" id=\"rb-data\">";
  html += base64(packed.data(), packed.size());
  html += "</script>\n<script>";
  html += kPlayerScript;
  html += "</script>\n</body>\n</html>\n";
  return html;
}

namespace {

const char kPlayerStyle[] = R"CSS(
:root{color-scheme:light dark;--fg:#1d1d1f;--bg:#fafafa;--pane:#fff;--line:#d0d0d4;--hi:#fff3b0;--err:#b00020;
 --muted:#5f5f66;--focus:#0b57d0}
@media (prefers-color-scheme:dark){:root{--fg:#e8e8ea;--bg:#18181a;--pane:#202024;--line:#3a3a40;--hi:#5a4a00;--err:#ff6b81;
 --muted:#a0a0a8;--focus:#8ab4f8}}
*{box-sizing:border-box}
body{margin:0;font:14px/1.4 system-ui,sans-serif;color:var(--fg);background:var(--bg)}
header{display:flex;gap:1em;align-items:baseline;padding:.5em 1em;border-bottom:1px solid var(--line)}
h1{font-size:1.1em;margin:0}h2{font-size:.9em;margin:.8em 0 .3em;text-transform:uppercase;letter-spacing:.05em;opacity:.7}
main{display:flex;flex-wrap:wrap;gap:1em;padding:1em}
#stage{flex:0 1 auto;max-width:100%;min-width:240px}
canvas{display:block;image-rendering:pixelated;border:1px solid var(--line);max-width:100%;height:auto}
#controls{display:flex;flex-wrap:wrap;gap:.4em;align-items:center;margin-top:.5em}
#controls label{white-space:nowrap}
#controls button{font:inherit;white-space:nowrap}
#timeline{flex:1 1 8em;min-width:8em}
#position{font-variant-numeric:tabular-nums;margin-top:.3em}
#banner{margin-top:.5em;padding:.4em .6em;border-left:4px solid var(--err);background:var(--pane)}
#banner.ok{border-left-color:#2e7d32}
#banner[hidden]{display:block;visibility:hidden}
aside{flex:1 1 320px;min-width:280px}
.pane{background:var(--pane);border:1px solid var(--line);margin:0;max-height:16em;overflow:auto;position:relative;
 font:12px/1.45 ui-monospace,'DejaVu Sans Mono',monospace;white-space:pre}
#source div{padding:0 .5em}#source div.now{background:var(--hi)}#source div.err{outline:2px solid var(--err)}
#source span.n{display:inline-block;min-width:3.5em;color:var(--muted);user-select:none}
#source div.now span.n{color:inherit}
#output{padding:.3em .5em;white-space:pre-wrap}
#pose,#sensors{font-variant-numeric:tabular-nums}
#sensors td{padding:0 .8em 0 0}#sensors tr.fresh{font-weight:bold}
#keys{font-size:.9em;margin:.3em 0 0}
:focus-visible{outline:3px solid var(--focus);outline-offset:2px}
.sr-only{position:absolute;width:1px;height:1px;padding:0;margin:-1px;overflow:hidden;clip:rect(0 0 0 0);white-space:nowrap;border:0}
)CSS";

const char kPlayerScript[] = R"JS(
'use strict';
(() => {
const meta = JSON.parse(document.getElementById('rb-meta').textContent);
const $ = (id) => document.getElementById(id);
const W = meta.width, H = meta.height;

class Reader {
  constructor(bytes) { this.b = bytes; this.p = 0; }
  u() { let v = 0, m = 1, x; do { x = this.b[this.p++]; v += (x & 127) * m; m *= 128; } while (x & 128); return v; }
  z() { const v = this.u(); return v % 2 ? -(v + 1) / 2 : v / 2; }
  f() { const d = new DataView(this.b.buffer, this.b.byteOffset + this.p, 8); this.p += 8; return d.getFloat64(0, true); }
  bytes(n) { const s = this.b.subarray(this.p, this.p + n); this.p += n; return s; }
}

async function unpack() {
  const text = $('rb-data').textContent.trim();
  const bin = atob(text);
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

// Colours as the canvas's 32-bit pixels (RGBA in memory order).
const little = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;
const pal = meta.palette.map((rgb) => {
  const r = (rgb >>> 16) & 255, g = (rgb >>> 8) & 255, b = rgb & 255;
  return little ? ((255 << 24) | (b << 16) | (g << 8) | r) >>> 0 : ((r << 24) | (g << 16) | (b << 8) | 255) >>> 0;
});

function decode(r) {
  const d = {};
  const nf = meta.frames;
  d.runStart = new Uint32Array(nf + 1);
  d.runLen = new Uint32Array(meta.runs); d.runCol = new Int32Array(meta.runs);
  let k = 0;
  for (let f = 0; f < nf; f++) {
    const c = r.u();
    d.runStart[f] = k;
    for (let j = 0; j < c; j++, k++) { d.runLen[k] = r.u(); d.runCol[k] = r.u() - 1; }
  }
  d.runStart[nf] = k;
  const n = meta.steps;
  const column = (zigzag) => {
    const a = new Float64Array(n);
    let v = 0;
    for (let i = 0; i < n; i++) { v += zigzag ? r.z() : r.u(); a[i] = v; }
    return a;
  };
  d.step = column(false); d.file = column(true); d.line = column(true); d.frame = column(true); d.out = column(true);
  d.flags = new Uint8Array(n);
  for (let i = 0; i < n; i++) d.flags[i] = r.u();
  d.qx = column(true); d.qy = column(true); d.qdx = column(true); d.qdy = column(true); d.qr = column(true);
  d.qh = column(true); d.colour = column(true);
  d.corrections = new Map();
  for (let c = 0, at = 0; c < meta.corrections; c++) {
    at += r.u();
    const count = r.u(), px = new Array(count);
    for (let j = 0, p = 0; j < count; j++) { p += r.z(); px[j] = p; }
    d.corrections.set(at, px);
  }
  const ne = meta.sensors;
  d.evStep = new Float64Array(ne); d.evName = new Uint32Array(ne); d.evValue = new Float64Array(ne);
  for (let e = 0, s = 0; e < ne; e++) {
    s += r.u(); d.evStep[e] = s; d.evName[e] = r.u();
    d.evValue[e] = r.u() === 0 ? r.z() : r.f();
  }
  d.playStep = new Uint32Array(meta.play); d.playMs = new Float64Array(meta.play);
  d.playPart = new Uint32Array(meta.play); d.playParts = new Uint32Array(meta.play);
  for (let i = 0, s = 0, t = 0; i < meta.play; i++) {
    s += r.u(); t += r.u(); d.playStep[i] = s; d.playMs[i] = t;
    d.playPart[i] = r.u(); d.playParts[i] = d.playPart[i] ? r.u() : 1;
  }
  d.output = r.bytes(r.u());
  return d;
}

function start(d) {
  const n = meta.steps;
  const ctx = $('screen').getContext('2d');
  const image = ctx.createImageData(W, H);
  const view = new Uint32Array(image.data.buffer);
  // The screen as palette indices; each keyframe is what changed since the one before, so the
  // page keeps the screen of every SNAP-th keyframe to seek backwards quickly (at most 64 of
  // them: about 60 MB).
  const screen = pal.length <= 65536 ? new Uint16Array(W * H) : new Uint32Array(W * H);
  const SNAP = Math.max(256, Math.ceil(meta.frames / 64));
  let frameShown = -1;
  const poseStart = new Int32Array(n);
  for (let i = 0; i < n; i++) poseStart[i] = i === 0 || d.flags[i] & 8 ? i : poseStart[i - 1];

  function apply(f) {
    let pos = 0;
    for (let k = d.runStart[f], e = d.runStart[f + 1]; k < e; k++) {
      const len = d.runLen[k], c = d.runCol[k];
      if (c >= 0) screen.fill(c, pos, pos + len);
      pos += len;
    }
  }
  const snaps = [];
  screen.fill(meta.white);
  for (let f = 0; f < meta.frames; f++) {
    apply(f);
    if (f % SNAP === 0) snaps.push(screen.slice());
  }
  frameShown = meta.frames - 1;
  function toFrame(f) {
    if (f === frameShown || meta.frames === 0) return;
    let g;
    if (f > frameShown && f - frameShown <= SNAP) g = frameShown + 1;
    else { const s = Math.floor(f / SNAP); screen.set(snaps[s]); g = s * SNAP + 1; }
    for (; g <= f; g++) apply(g);
    frameShown = f;
  }
  // rb render's robot (render/robot_image.h) at a centre, radius and heading vector.
  function cover(cx, cy, r, dx, dy) {
    const px = [];
    {
      const x0 = Math.max(0, Math.floor(cx - r) - 2), x1 = Math.min(W - 1, Math.ceil(cx + r) + 2);
      const y0 = Math.max(0, Math.floor(cy - r) - 2), y1 = Math.min(H - 1, Math.ceil(cy + r) + 2);
      for (let v = y0; v <= y1; ++v) {
        for (let u = x0; u <= x1; ++u) {
          const x = u - cx, y = v - cy;
          const d2 = x * x + y * y;
          if (d2 > r * r) continue;
          const inner = r - 3;
          if (!(inner < 0 || d2 > inner * inner)) {
            let t = x * dx + y * dy;
            t = t < 0 ? 0 : t > r ? r : t;
            const ex = x - t * dx, ey = y - t * dy;
            if (!(ex * ex + ey * ey < 2.25)) continue;
          }
          px.push(v * W + u);
        }
      }
    }
    return px;
  }
  // The robot from the rounded pose, then the step's corrections.
  function robotPixels(i) {
    let px = [];
    if (d.flags[i] & 4) {
      px = cover(d.qx[i] / meta.posQ, d.qy[i] / meta.posQ, d.qr[i] / meta.posQ, d.qdx[i] / meta.dirQ, d.qdy[i] / meta.dirQ);
    }
    const fix = d.corrections.get(poseStart[i]);
    if (fix && d.flags[i] & 1) {
      const set = new Set(px);
      for (const p of fix) { if (set.has(p)) set.delete(p); else set.add(p); }
      px = Array.from(set);
    }
    return px;
  }

  // Glides (render/animation.cpp, glideImage): part j of m of the way from step i to the next,
  // the same operations as there, so the canvas is the GIF's frame.
  function headingUnit(h) {
    const q = Math.floor(h / 90 + 0.5);
    const r = (h - q * 90) * (3.141592653589793 / 180);
    const r2 = r * r;
    const s = r * (1 - r2 / 6 * (1 - r2 / 20 * (1 - r2 / 42 * (1 - r2 / 72 * (1 - r2 / 110 * (1 - r2 / 156))))));
    const c = 1 - r2 / 2 * (1 - r2 / 12 * (1 - r2 / 30 * (1 - r2 / 56 * (1 - r2 / 90 * (1 - r2 / 132)))));
    const k = ((q % 4) + 4) % 4;
    const sinH = k === 0 ? s : k === 1 ? c : k === 2 ? -s : -c;
    const cosH = k === 0 ? c : k === 1 ? -s : k === 2 ? -c : s;
    return [sinH, -cosH];
  }
  function glide(i, j, m) {
    const P = meta.posQ, t = j / m;
    shownPlay = -1;
    const ax = d.qx[i] / P, ay = d.qy[i] / P, bx = d.qx[i + 1] / P, by = d.qy[i + 1] / P, r = d.qr[i] / P;
    current = i;
    toFrame(d.frame[i]);
    for (let p = 0; p < W * H; p++) view[p] = pal[screen[p]];
    let px;
    if (d.qx[i] === d.qx[i + 1] && d.qy[i] === d.qy[i + 1]) {
      const h0 = d.qh[i] / P;
      let turn = d.qh[i + 1] / P - h0;
      if (turn > 180) turn -= 360;
      else if (turn <= -180) turn += 360;
      const [dx, dy] = headingUnit(h0 + turn * t);
      px = cover(ax, ay, r, dx, dy);
    } else {
      // The pixels the move changes, where they lie behind the robot along its way.
      const ux = bx - ax, uy = by - ay, l2 = ux * ux + uy * uy;
      for (let f = d.frame[i] + 1; f <= d.frame[i + 1]; f++) {
        let pos = 0;
        for (let k = d.runStart[f], e = d.runStart[f + 1]; k < e; k++) {
          const len = d.runLen[k], c = d.runCol[k];
          if (c >= 0) {
            for (let p = pos; p < pos + len; p++) {
              const x = p % W, y = (p - x) / W;
              if ((x - ax) * ux + (y - ay) * uy <= t * l2) view[p] = pal[c];
            }
          }
          pos += len;
        }
      }
      px = cover(ax + (bx - ax) * t, ay + (by - ay) * t, r, d.qdx[i] / meta.dirQ, d.qdy[i] / meta.dirQ);
    }
    const c = pal[d.colour[i]];
    for (const p of px) view[p] = c;
    ctx.putImageData(image, 0, 0);
    timeline.value = String(i);
    timeline.setAttribute('aria-valuetext', 'step ' + (i + 1) + ' of ' + n);
    panes(i);
    say(describe(i), false);
  }

  // The panes.
  const lines = meta.source.split(/\r?\n/);
  const sourcePane = $('source');
  const lineEls = lines.map((text, k) => {
    const div = document.createElement('div');
    const num = document.createElement('span');
    num.className = 'n';
    num.textContent = String(k + 1);
    div.append(num, text);
    sourcePane.append(div);
    return div;
  });
  $('title').textContent = meta.name;
  document.title = meta.name + ' \u2014 rb replay';
  const timeline = $('timeline');
  timeline.max = String(n - 1);
  const decoder = new TextDecoder();
  const byName = meta.sensorNames.map(() => []);
  for (let e = 0; e < meta.sensors; e++) byName[d.evName[e]].push(e);
  const ended = {
    'finished': 'the program ended',
    'runtime error': 'stopped by a runtime error',
    'step limit': 'stopped at the step limit (--max-steps)',
    'timeout': 'stopped at the time limit (--timeout)',
    'stopped': 'stopped',
  }[meta.status] || meta.status;
  $('ending').textContent = ended + ' after ' + meta.totalSteps + ' statements' +
      (meta.stride > 1 ? ' (1 statement in ' + meta.stride + ' kept)' : '');
  const fmt = (v) => (Math.round(v * 100) / 100).toFixed(2);
  const where = (file, line) => (file === meta.file ? 'line ' + line : 'line ' + line + ' of an included file');

  // The screen as text for screen readers (#describe, aria-live polite): the step and its line,
  // the robot's pose and pen, the sensors last read and the last line printed, from the
  // recording. While playing it is said at most every 2 s; after a step by hand, a moment after
  // the last one; the end at once, with the run's error (#alert, role alert) and its line.
  const said = {text: '', at: -Infinity, pending: null, timer: 0};
  function sayNow() {
    clearTimeout(said.timer);
    said.timer = 0;
    const text = said.pending;
    said.pending = null;
    if (text === null || text === said.text) return;
    $('describe').textContent = text;
    said.text = text;
    said.at = performance.now();
  }
  function say(text, byHand) {
    said.pending = text;
    if (said.timer && !byHand) return;  // the timer set says the latest
    clearTimeout(said.timer);
    said.timer = setTimeout(sayNow, byHand ? 250 : Math.max(0, said.at + 2000 - performance.now()));
  }
  const num = (v) => String(Math.round(v * 10) / 10);
  // The last line printed by step i that is not blank (at most 200 bytes of it).
  function lastPrinted(i) {
    let e = Math.min(d.out[i], d.output.length);
    for (let looked = 0; e > 0 && looked < 65536;) {
      let b = e;
      while (b > 0 && d.output[b - 1] !== 10) b--;
      const line = decoder.decode(d.output.subarray(b, Math.min(e, b + 200))).replace(/\r$/, '');
      if (line.trim()) return line;
      looked += e - b + 1;
      e = b - 1;
    }
    return '';
  }
  // The last reading of each sensor before step i: [sensor, event], the latest first.
  function readings(i) {
    const s = d.step[i];
    const rows = [];
    for (let k = 0; k < byName.length; k++) {
      const list = byName[k];
      let lo = 0, hi = list.length;
      while (lo < hi) { const mid = (lo + hi) >> 1; if (d.evStep[list[mid]] < s) lo = mid + 1; else hi = mid; }
      if (lo > 0) rows.push([k, list[lo - 1]]);
    }
    rows.sort((a, b) => d.evStep[b[1]] - d.evStep[a[1]] || a[0] - b[0]);
    return rows;
  }
  function endText() {
    return meta.error ? ended + ' at ' + where(meta.error.file, meta.error.line) + ': ' + meta.error.message : ended + '.';
  }
  function describe(i) {
    const f = d.flags[i];
    const parts = ['Step ' + (i + 1) + ' of ' + n + (i === n - 1 ? ', the end: ' + endText().replace(/\.?$/, '.')
        : ', ' + where(d.file[i], d.line[i]) + ' about to run.')];
    parts.push(f & 1 ? 'Robot at x ' + num(d.qx[i] / meta.posQ) + ', y ' + num(d.qy[i] / meta.posQ) + ', heading ' +
        num(d.qh[i] / meta.posQ) + ' degrees, pen ' + (f & 2 ? 'down' : 'up') + '.' : 'The robot is not placed yet.');
    const rows = readings(i).slice(0, 5);
    if (rows.length) parts.push('Last read: ' + rows.map(([k, e]) => meta.sensorNames[k] + ' ' + d.evValue[e] +
        ' (statement ' + (d.evStep[e] + 1) + ')').join(', ') + '.');
    const printed = lastPrinted(i);
    if (printed) parts.push('Printed: ' + printed);
    return parts.join(' ');
  }

  let current = -1, lineShown = null, errShown = null, outShown = -1;
  let shownPlay = -1;  // the frame of the animation last shown by playing (-1: a step by hand)
  function panes(i) {
    const s = d.step[i];
    $('position').textContent = 'step ' + (i + 1) + ' of ' + n + ' \u00b7 ' +
        (i === n - 1 ? 'after the last statement (' + meta.totalSteps + ' run)' : 'statement ' + (s + 1) + ' about to run');
    if (lineShown) lineShown.classList.remove('now');
    lineShown = null;
    if (d.file[i] === meta.file && d.line[i] > 0 && d.line[i] <= lineEls.length) {
      lineShown = lineEls[d.line[i] - 1];
      lineShown.classList.add('now');
      const top = lineShown.offsetTop, pane = sourcePane;
      if (top < pane.scrollTop || top + lineShown.offsetHeight > pane.scrollTop + pane.clientHeight)
        pane.scrollTop = Math.max(0, top - pane.clientHeight / 3);
    }
    if (errShown) errShown.classList.remove('err');
    errShown = null;
    // The end's banner keeps its place (hidden, not removed) so the screen keeps its size.
    $('banner').hidden = i !== n - 1;
    if (i === n - 1 && meta.error && meta.error.file === meta.file && meta.error.line > 0 &&
        meta.error.line <= lineEls.length) {
      errShown = lineEls[meta.error.line - 1];
      errShown.classList.add('err');
    }
    const f = d.flags[i];
    $('pose').textContent = f & 1
        ? 'x ' + fmt(d.qx[i] / meta.posQ) + '  y ' + fmt(d.qy[i] / meta.posQ) + '  heading ' +
          fmt(d.qh[i] / meta.posQ) + '\u00b0  pen ' + (f & 2 ? 'down' : 'up')
        : 'not placed yet (rLocate)';
    const rows = readings(i);
    const table = $('sensors');
    table.replaceChildren(...rows.map(([k, e]) => {
      const tr = document.createElement('tr');
      if (d.evStep[e] === s - 1) tr.className = 'fresh';
      for (const text of [meta.sensorNames[k], String(d.evValue[e]), 'statement ' + (d.evStep[e] + 1)]) {
        const td = document.createElement('td');
        td.textContent = text;
        tr.append(td);
      }
      return tr;
    }));
    if (rows.length === 0) table.textContent = 'none yet';
    const end = Math.min(d.out[i], d.output.length);
    if (end !== outShown) {
      outShown = end;
      const from = Math.max(0, end - 65536);
      let text = (from > 0 ? '\u2026' : '') + decoder.decode(d.output.subarray(from, end));
      if (d.out[i] > d.output.length) text += '\n\u2026 (the output past the first ' + d.output.length + ' bytes was not kept)';
      const out = $('output');
      out.textContent = text;
      out.scrollTop = out.scrollHeight;
    }
    let read = 0;
    while (read < meta.inputs.length && meta.inputs[read][0] < s) read++;
    const last = meta.inputs.slice(Math.max(0, read - 10), read).map((x) => JSON.stringify(x[1]));
    $('inputs').textContent = read === 0 ? '' : 'input read: ' + read + ' line' + (read > 1 ? 's' : '') +
        (read > 10 ? ', the last 10: \u2026 ' : ': ') + last.join(', ');
  }

  function show(i) {
    i = Math.max(0, Math.min(n - 1, Math.round(i)));
    current = i;
    shownPlay = -1;
    toFrame(d.frame[i]);
    for (let p = 0; p < W * H; p++) view[p] = pal[screen[p]];
    const c = pal[d.colour[i]];
    for (const p of robotPixels(i)) view[p] = c;
    ctx.putImageData(image, 0, 0);
    timeline.value = String(i);
    timeline.setAttribute('aria-valuetext', 'step ' + (i + 1) + ' of ' + n);
    panes(i);
    if (i === n - 1 && (playing || !said.text.includes(', the end: '))) {
      // The end: said at once, the error too.
      said.pending = describe(i);
      sayNow();
      if (meta.error) { $('alert').textContent = ''; $('alert').textContent = endText(); }
    } else {
      say(describe(i), !playing);
    }
  }

  // Playing: the animation's frames at their times, times the speed.
  let playing = false, timer = 0, next = 0, baseMs = 0, anchor = 0;
  const speed = () => Number($('speed').value) || 1;
  let rate = speed();
  const playButton = $('play');
  function firstAfter(i) {
    let lo = 0, hi = meta.play;
    while (lo < hi) { const mid = (lo + hi) >> 1; if (d.playStep[mid] <= i) lo = mid + 1; else hi = mid; }
    return lo;
  }
  function tick() {
    timer = 0;
    if (!playing) return;
    const t = baseMs + (performance.now() - anchor) * rate;
    let k = next;
    while (k < meta.play && d.playMs[k] <= t) k++;
    if (k > next) {
      next = k;
      if (d.playPart[k - 1]) glide(d.playStep[k - 1], d.playPart[k - 1], d.playParts[k - 1]);
      else show(d.playStep[k - 1]);
      shownPlay = k - 1;
    }
    if (next >= meta.play) { pause(); return; }
    timer = setTimeout(tick, Math.max(1, Math.min(250, (d.playMs[next] - t) / rate)));
  }
  function play() {
    if (playing) return;
    if (current >= n - 1) show(0);
    playing = true;
    playWord('\u25A0 ', 'pause');
    // Paused inside a glide: on from its frame; else from the first frame after the step shown.
    next = shownPlay >= 0 && d.playStep[shownPlay] === current ? shownPlay + 1 : firstAfter(current);
    baseMs = next > 0 ? d.playMs[next - 1] : 0;
    anchor = performance.now();
    rate = speed();
    tick();
  }
  function pause() {
    playing = false;
    if (timer) clearTimeout(timer);
    timer = 0;
    playWord('\u25B6 ', 'play');
  }
  function playWord(symbol, word) {
    const span = document.createElement('span');
    span.setAttribute('aria-hidden', 'true');
    span.textContent = symbol;
    playButton.replaceChildren(span, word);
  }
  playButton.addEventListener('click', () => (playing ? pause() : play()));
  $('back').addEventListener('click', () => { pause(); show(current - 1); });
  $('forward').addEventListener('click', () => { pause(); show(current + 1); });
  timeline.addEventListener('input', () => { pause(); show(Number(timeline.value)); });
  $('speed').addEventListener('change', () => {
    // Keep the time reached; go on from it at the new speed.
    const now = performance.now();
    baseMs += (now - anchor) * rate;
    anchor = now;
    rate = speed();
  });
  document.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    // A focused button takes Space and Enter itself (a click).
    if (e.target instanceof HTMLButtonElement && (e.key === ' ' || e.key === 'Enter')) return;
    if (e.key === ' ') { e.preventDefault(); playing ? pause() : play(); }
    else if (e.key === 'ArrowLeft') { pause(); show(current - 1); }
    else if (e.key === 'ArrowRight') { pause(); show(current + 1); }
    else if (e.key === 'Home') { pause(); show(0); }
    else if (e.key === 'End') { pause(); show(n - 1); }
  });
  {
    const banner = $('banner');
    banner.className = meta.error ? '' : 'ok';
    banner.textContent = meta.error ? endText() : ended + '.';
  }
  // The screen as large as fits with the controls under it in the window (or the report's
  // frame), at most its own size (--scale), at least 240 pixels wide.
  function fit() {
    const c = $('screen'), stage = $('stage'), main = stage.parentElement;
    const pad = parseFloat(getComputedStyle(main).paddingLeft) + parseFloat(getComputedStyle(main).paddingRight);
    let w = Math.max(240, Math.min(W * meta.scale, Math.floor(main.clientWidth - pad)));
    // Smaller until the stage ends in the window (the controls may wrap as it narrows).
    for (let pass = 0; pass < 8; pass++) {
      c.style.width = w + 'px';
      stage.style.width = w + 'px';  // the controls under the screen, as wide as it
      const over = stage.getBoundingClientRect().bottom + scrollY + 8 - innerHeight;
      if (over <= 0 || w <= 240) break;
      w = Math.max(240, Math.floor(w - Math.max(1, over) * W / H));
    }
  }
  let fitting = 0;
  addEventListener('resize', () => { if (!fitting) fitting = requestAnimationFrame(() => { fitting = 0; fit(); }); });
  show(0);
  fit();
  // Playing on opening: the box's state as the viewer last set it on this computer, else the
  // replay's own (rb render --autoplay, rb test's replays), never when the viewer asks for
  // reduced motion; it starts once the screen is in view, unless someone moved it already.
  const auto = $('autoplay');
  let stored = null;
  try { stored = localStorage.getItem('rb-replay-autoplay'); } catch (e) { stored = null; }
  const reduced = matchMedia('(prefers-reduced-motion: reduce)').matches;
  auto.checked = stored === '1' || stored === '0' ? stored === '1' : Boolean(meta.autoplay) && !reduced;
  auto.addEventListener('change', () => {
    try { localStorage.setItem('rb-replay-autoplay', auto.checked ? '1' : '0'); } catch (e) { /* not kept */ }
  });
  let moved = false;
  for (const id of ['back', 'forward', 'timeline']) $(id).addEventListener('input', () => { moved = true; });
  for (const id of ['back', 'play', 'forward']) $(id).addEventListener('click', () => { moved = true; });
  document.addEventListener('keydown', () => { moved = true; });
  if (auto.checked) {
    const seen = new IntersectionObserver((entries) => {
      if (!entries.some((e) => e.isIntersecting) || document.visibilityState !== 'visible') return;
      seen.disconnect();
      if (!moved && !playing && current === 0) play();
    }, {threshold: 0.5});
    seen.observe($('screen'));
    document.addEventListener('visibilitychange', () => { seen.unobserve($('screen')); seen.observe($('screen')); });
  }
  return {
    get step() { return current; },
    get playing() { return playing; },
    count: n,
    show, play, pause, glide,
    // The frames that play: [step, part, parts] each (part 0: the step itself).
    get frames() { return Array.from(d.playStep, (st, k) => [st, d.playPart[k], d.playParts[k]]); },
  };
}

// window.rbPlayer: the player's state and actions once `ready` resolves (tests drive it).
const player = {};
window.rbPlayer = player;
player.ready = (async () => {
    try {
      Object.defineProperties(player, Object.getOwnPropertyDescriptors(start(decode(new Reader(await unpack())))));
    } catch (e) {
      $('banner').hidden = false;
      $('banner').textContent = 'This replay cannot play here: ' + e;
      throw e;
    }
})();
})();
)JS";

}  // namespace

std::string animationFormat(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".gif") return "gif";
  if (ext == ".svg") return "svg";
  if (ext == ".html" || ext == ".htm") return "html";
  return "";
}

std::string encodeAnimation(const std::string& format, const Recording& recording, const PlayerSource& source,
                            const AnimationOptions& options) {
  if (format == "gif") {
    const std::vector<uint8_t> gif = encodeGif(recording, options);
    return std::string(gif.begin(), gif.end());
  }
  return format == "svg" ? animatedSvg(recording, options) : htmlPlayer(recording, source, options);
}

bool writeAnimation(const std::string& path, const Recording& recording, const PlayerSource& source,
                    const AnimationOptions& options, std::string& error) {
  const std::string format = animationFormat(path);
  if (format.empty()) {
    error = "cannot tell the format of '" + path + "': the name must end in .gif, .svg or .html";
    return false;
  }
  try {
    const std::string bytes = encodeAnimation(format, recording, source, options);
    return writeFileBytes(path, bytes.data(), bytes.size(), error);
  } catch (const std::exception& e) {
    error = "cannot write '" + path + "': " + e.what();
    return false;
  }
}

}  // namespace rb::render
