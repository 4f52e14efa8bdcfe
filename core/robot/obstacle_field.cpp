#include "robot/obstacle_field.h"

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
}

}  // namespace rb
