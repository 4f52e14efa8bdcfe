#pragma once
// The distance from every pixel to the nearest obstacle pixel (the screen edge counts as a
// wall), rebuilt lazily when the canvas's obstacles change. With it, the simulator answers
// "is anything near?" with one lookup: crash checks and sensors only scan pixels when the
// robot is close to something, and rays skip across open space.
//
// A few new obstacle pixels in a known box (the robot's own pen trail, one step at a time) are
// added without a rebuild: distances within kLocalReach of them become exact, and until the
// next rebuild every distance is capped at kLocalReach, so the field stays a lower bound
// everywhere and exact wherever it is below the cap.

#include <cstdint>
#include <vector>

#include "screen/canvas.h"

namespace rb {

class ObstacleField {
 public:
  explicit ObstacleField(const Canvas& canvas) : canvas_(canvas) {}

  /// How far around new obstacle pixels a local update makes the distances exact.
  static constexpr float kLocalReach = 64;
  /// At most this many new obstacle pixels are added locally; more make a rebuild.
  static constexpr size_t kLocalMaxPixels = 256;

  /// Euclidean distance from pixel (x, y) to the nearest obstacle pixel; 0 on an obstacle and
  /// outside the screen. After a local update (see changedWithin) it is capped at kLocalReach:
  /// never more than the true distance, and exact below the cap.
  float distance(int x, int y) {
    refresh();
    if (!Canvas::inside(x, y)) return 0;
    float d = dist_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)];
    return capped_ && d > kLocalReach ? kLocalReach : d;
  }

  /// The canvas's obstacles changed only inside the box [x0, x1] x [y0, y1] (inclusive) since
  /// they had version `before`. When the field was current at `before` and the change only
  /// added a few obstacle pixels, the field catches up locally; otherwise the next query
  /// rebuilds it as usual.
  void changedWithin(int x0, int y0, int x1, int y1, uint64_t before);

  /// Whether pixel (x, y) is an obstacle (outside the screen: the wall). The same answer as
  /// Canvas::isObstacle, from a mask built with the field.
  bool obstacle(int x, int y) {
    refresh();
    if (x < -1 || y < -1 || x > Canvas::kWidth || y > Canvas::kHeight) return true;
    return mask_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)] != 0;
  }

 private:
  static constexpr int kW = Canvas::kWidth + 2;   // with a one-pixel wall all around
  static constexpr int kH = Canvas::kHeight + 2;
  void refresh() {
    if (builtFor_ != canvas_.obstacleVersion()) rebuild();
  }
  void rebuild();

  const Canvas& canvas_;
  uint64_t builtFor_ = 0;
  bool capped_ = false;        ///< a local update happened since the last rebuild
  std::vector<float> dist_;
  std::vector<uint8_t> mask_;  ///< 1 where a pixel is an obstacle, with the wall around
};

}  // namespace rb
