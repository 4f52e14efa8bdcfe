#pragma once
// The distance from every pixel to the nearest obstacle pixel (the screen edge counts as a
// wall). With it, the simulator answers "is anything near?" with one lookup: crash checks and
// sensors only scan pixels when the robot is close to something, and rays skip across open
// space.
//
// The field follows the canvas lazily and by region. A change everywhere (clearScr, rInvisible,
// scrolling) or over a large area rebuilds it at the next query. A change in a small box (status
// text redrawn in a loop, the robot's own pen trail) is only queued: until a query comes within
// kLocalReach of the box, nothing is computed, because nothing farther can be affected. Then
// the distances within kLocalReach of the box are recomputed from the obstacles around it.
// While changes are queued or have been applied locally, every distance is capped at
// kLocalReach: the field stays a lower bound everywhere and is exact wherever it is below the
// cap, which is all the simulator needs.

#include <cstdint>
#include <vector>

#include "screen/canvas.h"

namespace rb {

class ObstacleField {
 public:
  explicit ObstacleField(Canvas& canvas) : canvas_(canvas) {}

  /// How far around a changed box a local update makes the distances exact.
  static constexpr int kLocalReach = 64;
  /// A changed box larger than this (in pixels) makes a rebuild instead of a local update.
  static constexpr long kLocalMaxArea = 40000;
  /// At most this many boxes wait; more are merged into one.
  static constexpr size_t kMaxPending = 8;

  /// Euclidean distance from pixel (x, y) to the nearest obstacle pixel; 0 on an obstacle and
  /// outside the screen. After a local update it is capped at kLocalReach: never more than the
  /// true distance, and exact below the cap.
  float distance(int x, int y) {
    settle(x, y);
    if (!Canvas::inside(x, y)) return 0;
    float d = dist_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)];
    return capped_ && d > float(kLocalReach) ? float(kLocalReach) : d;
  }

  /// Whether pixel (x, y) is an obstacle (outside the screen: the wall). The same answer as
  /// Canvas::isObstacle.
  bool obstacle(int x, int y) {
    settle(x, y);
    if (x < -1 || y < -1 || x > Canvas::kWidth || y > Canvas::kHeight) return true;
    return mask_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)] != 0;
  }

  /// Statistics, for tests: full rebuilds and local updates so far.
  uint64_t rebuilds() const { return rebuilds_; }
  uint64_t localUpdates() const { return localUpdates_; }

 private:
  static constexpr int kW = Canvas::kWidth + 2;   // with a one-pixel wall all around
  static constexpr int kH = Canvas::kHeight + 2;

  /// Brings the field up to date for a query at (x, y): takes the canvas's new changes, and
  /// applies the queued boxes that could matter there.
  void settle(int x, int y) {
    if (builtFor_ != canvas_.obstacleVersion()) takeChanges();
    if (!pending_.empty() && x >= near_.x0 && x <= near_.x1 && y >= near_.y0 && y <= near_.y1)
      applyNear(x, y);
  }
  void takeChanges();
  void applyNear(int x, int y);
  void rebuild();
  /// Recomputes the distances within kLocalReach of `box` (canvas pixels) from the canvas.
  void update(const PixelBox& box);
  void recomputeNear();

  Canvas& canvas_;
  uint64_t builtFor_ = 0;
  bool capped_ = false;           ///< distances are capped at kLocalReach (see above)
  std::vector<PixelBox> pending_; ///< changed boxes not yet applied
  PixelBox near_;                 ///< the pending boxes grown by kLocalReach: queries there settle
  std::vector<float> dist_;
  std::vector<uint8_t> mask_;     ///< 1 where a pixel is an obstacle, with the wall around
  uint64_t rebuilds_ = 0, localUpdates_ = 0;
  // Scratch space of the distance transforms.
  std::vector<float> f_, out_, z_, window_;
  std::vector<int> v_;
};

}  // namespace rb
