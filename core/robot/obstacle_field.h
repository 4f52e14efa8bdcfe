#pragma once
// The distance from every pixel to the nearest obstacle pixel (the screen edge counts as a
// wall), rebuilt lazily when the canvas's obstacles change. With it, the simulator answers
// "is anything near?" with one lookup: crash checks and sensors only scan pixels when the
// robot is close to something, and rays skip across open space.

#include <cstdint>
#include <vector>

#include "screen/canvas.h"

namespace rb {

class ObstacleField {
 public:
  explicit ObstacleField(const Canvas& canvas) : canvas_(canvas) {}

  /// Euclidean distance from pixel (x, y) to the nearest obstacle pixel; 0 on an obstacle and
  /// outside the screen.
  float distance(int x, int y) {
    refresh();
    if (!Canvas::inside(x, y)) return 0;
    return dist_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)];
  }

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
  std::vector<float> dist_;
  std::vector<uint8_t> mask_;  ///< 1 where a pixel is an obstacle, with the wall around
};

}  // namespace rb
