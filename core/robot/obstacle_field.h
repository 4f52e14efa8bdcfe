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
//
// A queued box that, once a query comes near, turns out to have only added obstacle pixels
// (the pen trail in an obstacle colour, one step at a time) can only bring distances down: the
// new distance is the smaller of the old one and the distance to the new pixels. Those pixels
// go into the mask and into a short list (`fresh_`), and a query takes the minimum over the
// ones within the cap, instead of a local update around every step's few pixels. A list that
// grows past kMaxFresh pixels, or a later change that removes an obstacle where it lies, is
// recomputed by a local update like any other change. Either way the answers are the same.

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
  /// At most this many added pixels in one group of fresh pixels (and this many groups) are
  /// kept as a list; past that the group becomes a queued box.
  static constexpr size_t kMaxFresh = 1024;
  static constexpr size_t kMaxFreshGroups = 8;

  /// Euclidean distance from pixel (x, y) to the nearest obstacle pixel; 0 on an obstacle and
  /// outside the screen. After a local update it is capped at kLocalReach: never more than the
  /// true distance, and exact below the cap.
  float distance(int x, int y) {
    settle(x, y);
    if (!Canvas::inside(x, y)) return 0;
    float d = dist_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)];
    if (capped_ && d > float(kLocalReach)) d = float(kLocalReach);
    return fresh_.empty() ? d : freshDistance(x, y, d);
  }

  /// Whether pixel (x, y) is an obstacle (outside the screen: the wall). The same answer as
  /// Canvas::isObstacle.
  bool obstacle(int x, int y) {
    settle(x, y);
    if (x < -1 || y < -1 || x > Canvas::kWidth || y > Canvas::kHeight) return true;
    return mask_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)] != 0;
  }

  /// Statistics, for tests: full rebuilds and local updates so far, and the added pixels now
  /// kept as a list.
  uint64_t rebuilds() const { return rebuilds_; }
  uint64_t localUpdates() const { return localUpdates_; }
  size_t freshPixels() const {
    size_t n = 0;
    for (const Fresh& f : fresh_) n += f.pixels.size();
    return n;
  }

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
  /// Pixels that became obstacles and whose distances are not in `dist_` yet, with their box.
  struct Fresh {
    PixelBox box;
    std::vector<uint32_t> pixels;  ///< y << 16 | x, canvas pixels
  };

  void takeChanges();
  /// Applies a changed box: when it only added obstacle pixels they join `fresh_`; otherwise a
  /// local update recomputes the distances around it.
  void apply(const PixelBox& box);
  /// The smaller of `d` and the distance from (x, y) to the nearest fresh pixel.
  float freshDistance(int x, int y, float d) const;
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
  std::vector<Fresh> fresh_;      ///< added pixels not yet in `dist_` (the mask has them)
  std::vector<uint32_t> added_;   ///< scratch: one box's added pixels
  uint64_t rebuilds_ = 0, localUpdates_ = 0;
  // Scratch space of the distance transforms.
  std::vector<float> f_, out_, z_, window_;
  std::vector<int> v_;
};

}  // namespace rb
