#include "robot/obstacle_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rb {

namespace {

/// One-dimensional squared distance transform (Felzenszwalb and Huttenlocher, "Distance
/// Transforms of Sampled Functions", 2012): out[q] = min over p of (q - p)^2 + f[p].
void transform1d(const float* f, int n, float* out, int* v, float* z) {
  const float inf = std::numeric_limits<float>::infinity();
  int k = 0;
  v[0] = 0;
  z[0] = -inf;
  z[1] = inf;
  for (int q = 1; q < n; ++q) {
    if (f[q] == inf) continue;
    if (f[v[k]] == inf) {  // no finite parabola yet: this one replaces the placeholder
      v[k] = q;
      continue;
    }
    float s;
    for (;;) {
      int p = v[k];
      s = ((f[q] + float(q) * float(q)) - (f[p] + float(p) * float(p))) / float(2 * q - 2 * p);
      if (s <= z[k] && k > 0) --k;
      else break;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = inf;
  }
  if (f[v[0]] == inf) {
    for (int q = 0; q < n; ++q) out[q] = inf;
    return;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < float(q)) ++k;
    float d = float(q - v[k]);
    out[q] = d * d + f[v[k]];
  }
}

}  // namespace

void ObstacleField::rebuild() {
  const float inf = std::numeric_limits<float>::infinity();
  dist_.assign(static_cast<size_t>(kW) * kH, inf);
  mask_.assign(static_cast<size_t>(kW) * kH, 0);
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      bool wall = x == 0 || y == 0 || x == kW - 1 || y == kH - 1;
      if (wall || canvas_.isObstacleColour(canvas_.at(x - 1, y - 1))) {
        dist_[static_cast<size_t>(y) * kW + static_cast<size_t>(x)] = 0;
        mask_[static_cast<size_t>(y) * kW + static_cast<size_t>(x)] = 1;
      }
    }
  }
  int n = kW > kH ? kW : kH;
  std::vector<float> f(static_cast<size_t>(n)), out(static_cast<size_t>(n)), z(static_cast<size_t>(n) + 1);
  std::vector<int> v(static_cast<size_t>(n));
  for (int x = 0; x < kW; ++x) {  // columns
    for (int y = 0; y < kH; ++y) f[static_cast<size_t>(y)] = dist_[static_cast<size_t>(y) * kW + static_cast<size_t>(x)];
    transform1d(f.data(), kH, out.data(), v.data(), z.data());
    for (int y = 0; y < kH; ++y) dist_[static_cast<size_t>(y) * kW + static_cast<size_t>(x)] = out[static_cast<size_t>(y)];
  }
  for (int y = 0; y < kH; ++y) {  // rows
    float* row = dist_.data() + static_cast<size_t>(y) * kW;
    for (int x = 0; x < kW; ++x) f[static_cast<size_t>(x)] = row[x];
    transform1d(f.data(), kW, out.data(), v.data(), z.data());
    for (int x = 0; x < kW; ++x) row[x] = std::sqrt(out[static_cast<size_t>(x)]);
  }
  builtFor_ = canvas_.obstacleVersion();
  capped_ = false;
}

void ObstacleField::changedWithin(int x0, int y0, int x1, int y1, uint64_t before) {
  if (dist_.empty() || builtFor_ != before || builtFor_ == canvas_.obstacleVersion()) return;
  x0 = std::max(x0, 0), y0 = std::max(y0, 0);
  x1 = std::min(x1, Canvas::kWidth - 1), y1 = std::min(y1, Canvas::kHeight - 1);
  // Field coordinates (with the wall around) of the pixels that became obstacles. A pixel that
  // stopped being one, or too many new ones, leave the field stale: the next query rebuilds.
  struct Cell { int x, y; };
  std::vector<Cell> added;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      bool now = canvas_.isObstacleColour(canvas_.at(x, y));
      bool was = mask_[static_cast<size_t>(y + 1) * kW + static_cast<size_t>(x + 1)] != 0;
      if (now == was) continue;
      if (!now || added.size() == kLocalMaxPixels) return;
      added.push_back({x + 1, y + 1});
    }
  int bx0 = kW, by0 = kH, bx1 = -1, by1 = -1;
  for (const Cell& c : added) {
    size_t i = static_cast<size_t>(c.y) * kW + static_cast<size_t>(c.x);
    mask_[i] = 1;
    dist_[i] = 0;
    bx0 = std::min(bx0, c.x), by0 = std::min(by0, c.y), bx1 = std::max(bx1, c.x), by1 = std::max(by1, c.y);
  }
  // Within kLocalReach of the new pixels every distance becomes exact; beyond it the new pixels
  // are farther than the cap, so min(old distance, cap) stays a lower bound.
  const int reach = static_cast<int>(kLocalReach);
  for (int y = std::max(by0 - reach, 0); y <= std::min(by1 + reach, kH - 1); ++y) {
    float* row = dist_.data() + static_cast<size_t>(y) * kW;
    int gy = y < by0 ? by0 - y : (y > by1 ? y - by1 : 0);
    for (int x = std::max(bx0 - reach, 0); x <= std::min(bx1 + reach, kW - 1); ++x) {
      int gx = x < bx0 ? bx0 - x : (x > bx1 ? x - bx1 : 0);
      float old = row[x];
      // No new pixel is nearer than the box that holds them all.
      if (old * old <= float(gx * gx + gy * gy)) continue;
      float best = old * old;
      for (const Cell& c : added) {
        float dx = float(x - c.x), dy = float(y - c.y);
        best = std::min(best, dx * dx + dy * dy);
      }
      row[x] = std::sqrt(best);
    }
  }
  if (!added.empty()) capped_ = true;
  builtFor_ = canvas_.obstacleVersion();
}

}  // namespace rb
