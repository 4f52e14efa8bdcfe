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

/// Squared Euclidean distance transform of a w x h grid in place (0 on obstacles, infinity
/// elsewhere on entry): columns, then rows.
void transform2d(float* grid, int w, int h, std::vector<float>& f, std::vector<float>& out,
                 std::vector<int>& v, std::vector<float>& z) {
  size_t n = static_cast<size_t>(std::max(w, h));
  f.resize(n), out.resize(n), v.resize(n), z.resize(n + 1);
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y) f[static_cast<size_t>(y)] = grid[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)];
    transform1d(f.data(), h, out.data(), v.data(), z.data());
    for (int y = 0; y < h; ++y) grid[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)] = out[static_cast<size_t>(y)];
  }
  for (int y = 0; y < h; ++y) {
    float* row = grid + static_cast<size_t>(y) * static_cast<size_t>(w);
    std::copy(row, row + w, f.begin());
    transform1d(f.data(), w, row, v.data(), z.data());
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
  transform2d(dist_.data(), kW, kH, f_, out_, v_, z_);
  for (float& d : dist_) d = std::sqrt(d);
  capped_ = false;
  pending_.clear();
  fresh_.clear();
  near_ = PixelBox{};
  ++rebuilds_;
}

void ObstacleField::takeChanges() {
  ChangeBoxes changes = canvas_.takeObstacleChanges();
  builtFor_ = canvas_.obstacleVersion();
  long area = 0;
  for (const PixelBox& b : changes.boxes) area += b.area();
  if (dist_.empty() || changes.all || area > kLocalMaxArea) {
    rebuild();
    return;
  }
  for (const PixelBox& box : changes.boxes) {
    capped_ = true;
    // A box that meets a waiting one (the same status line redrawn) joins it.
    bool joined = false;
    for (PixelBox& p : pending_) {
      const int j = ChangeBoxes::kJoin;
      if (box.x0 <= p.x1 + j && box.x1 >= p.x0 - j && box.y0 <= p.y1 + j && box.y1 >= p.y0 - j) {
        p.add(box);
        joined = true;
        break;
      }
    }
    if (!joined) pending_.push_back(box);
    if (pending_.size() > kMaxPending) {  // too many scattered boxes: apply the oldest now
      apply(pending_.front());
      pending_.erase(pending_.begin());
    }
  }
  recomputeNear();
}

void ObstacleField::apply(const PixelBox& changed) {
  PixelBox box;
  box.x0 = std::max(changed.x0, 0), box.y0 = std::max(changed.y0, 0);
  box.x1 = std::min(changed.x1, Canvas::kWidth - 1), box.y1 = std::min(changed.y1, Canvas::kHeight - 1);
  if (box.x0 > box.x1 || box.y0 > box.y1) return;
  // Compare the canvas with the mask: which pixels became obstacles, and did any stop being one?
  added_.clear();
  bool removed = false;
  for (int y = box.y0; y <= box.y1 && !removed; ++y) {
    const uint8_t* m = mask_.data() + static_cast<size_t>(y + 1) * kW + 1;
    for (int x = box.x0; x <= box.x1; ++x) {
      bool now = canvas_.isObstacleColour(canvas_.at(x, y));
      if (now == (m[x] != 0)) continue;
      if (!now) {
        removed = true;
        break;
      }
      added_.push_back(static_cast<uint32_t>(y) << 16 | static_cast<uint32_t>(x));
    }
  }
  if (removed) {
    // Distances may grow: a local update recomputes them, over the fresh pixels' groups the box
    // meets too (some of their pixels may be gone).
    PixelBox whole = box;
    for (size_t i = 0; i < fresh_.size();) {
      const PixelBox& f = fresh_[i].box;
      if (f.x0 <= box.x1 && f.x1 >= box.x0 && f.y0 <= box.y1 && f.y1 >= box.y0) {
        whole.add(f);
        fresh_.erase(fresh_.begin() + static_cast<long>(i));
      } else {
        ++i;
      }
    }
    update(whole);
    return;
  }
  if (added_.empty()) return;
  PixelBox addedBox;
  for (uint32_t p : added_) {
    mask_[static_cast<size_t>((p >> 16) + 1) * kW + (p & 0xffff) + 1] = 1;
    addedBox.add(static_cast<int>(p & 0xffff), static_cast<int>(p >> 16));
  }
  // Join the group it meets (the trail goes on from the last step), or start one.
  const int j = ChangeBoxes::kJoin;
  Fresh* group = nullptr;
  for (Fresh& f : fresh_)
    if (addedBox.x0 <= f.box.x1 + j && addedBox.x1 >= f.box.x0 - j && addedBox.y0 <= f.box.y1 + j &&
        addedBox.y1 >= f.box.y0 - j) {
      group = &f;
      break;
    }
  if (!group) {
    if (fresh_.size() >= kMaxFreshGroups) {  // too many scattered groups: the oldest is computed
      update(fresh_.front().box);
      fresh_.erase(fresh_.begin());
    }
    group = &fresh_.emplace_back();
  }
  group->box.add(addedBox);
  group->pixels.insert(group->pixels.end(), added_.begin(), added_.end());
  if (group->pixels.size() > kMaxFresh) {  // a long list costs every query near it: compute it
    update(group->box);
    fresh_.erase(fresh_.begin() + (group - fresh_.data()));
  }
}

float ObstacleField::freshDistance(int x, int y, float d) const {
  // Squared distances are whole numbers, exact in a float up to the screen's size, and the
  // square root of the smallest is the distance a rebuild would find.
  float best = d * d;
  for (const Fresh& f : fresh_) {
    int bx = std::max({f.box.x0 - x, 0, x - f.box.x1}), by = std::max({f.box.y0 - y, 0, y - f.box.y1});
    if (float(bx * bx + by * by) >= best) continue;
    for (uint32_t p : f.pixels) {
      int dx = static_cast<int>(p & 0xffff) - x, dy = static_cast<int>(p >> 16) - y;
      best = std::min(best, float(dx * dx + dy * dy));
    }
  }
  return best < d * d ? std::sqrt(best) : d;
}

void ObstacleField::recomputeNear() {
  near_ = PixelBox{};
  for (const PixelBox& b : pending_) {
    near_.add(b.x0 - kLocalReach, b.y0 - kLocalReach);
    near_.add(b.x1 + kLocalReach, b.y1 + kLocalReach);
  }
}

void ObstacleField::applyNear(int x, int y) {
  // Boxes within reach of (x, y) are applied; the others keep waiting.
  size_t kept = 0;
  for (size_t i = 0; i < pending_.size(); ++i) {
    const PixelBox b = pending_[i];
    bool near = x >= b.x0 - kLocalReach && x <= b.x1 + kLocalReach && y >= b.y0 - kLocalReach &&
                y <= b.y1 + kLocalReach;
    if (near) apply(b);
    else pending_[kept++] = b;
  }
  pending_.resize(kept);
  recomputeNear();
}

void ObstacleField::update(const PixelBox& box) {
  ++localUpdates_;
  const float inf = std::numeric_limits<float>::infinity();
  const int r = kLocalReach;
  // In field coordinates (with the wall around): the changed box, the region whose distances
  // it can change (within the reach), and the window of obstacles that decide them.
  int bx0 = std::max(box.x0, 0) + 1, by0 = std::max(box.y0, 0) + 1;
  int bx1 = std::min(box.x1, Canvas::kWidth - 1) + 1, by1 = std::min(box.y1, Canvas::kHeight - 1) + 1;
  for (int y = by0; y <= by1; ++y)
    for (int x = bx0; x <= bx1; ++x)
      mask_[static_cast<size_t>(y) * kW + static_cast<size_t>(x)] =
          canvas_.isObstacleColour(canvas_.at(x - 1, y - 1)) ? 1 : 0;
  int rx0 = std::max(bx0 - r, 0), ry0 = std::max(by0 - r, 0);
  int rx1 = std::min(bx1 + r, kW - 1), ry1 = std::min(by1 + r, kH - 1);
  int wx0 = std::max(rx0 - r, 0), wy0 = std::max(ry0 - r, 0);
  int wx1 = std::min(rx1 + r, kW - 1), wy1 = std::min(ry1 + r, kH - 1);
  int w = wx1 - wx0 + 1, h = wy1 - wy0 + 1;
  window_.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
  for (int y = 0; y < h; ++y) {
    const uint8_t* m = mask_.data() + static_cast<size_t>(y + wy0) * kW + static_cast<size_t>(wx0);
    float* row = window_.data() + static_cast<size_t>(y) * static_cast<size_t>(w);
    for (int x = 0; x < w; ++x) row[x] = m[x] ? 0.0f : inf;
  }
  transform2d(window_.data(), w, h, f_, out_, v_, z_);
  // Every obstacle within the reach of a pixel of the region lies in the window, so a distance
  // up to the reach is exact; a larger one only says "more than the reach".
  const float cap = float(r);
  for (int y = ry0; y <= ry1; ++y) {
    const float* src = window_.data() + static_cast<size_t>(y - wy0) * static_cast<size_t>(w);
    float* dst = dist_.data() + static_cast<size_t>(y) * kW;
    for (int x = rx0; x <= rx1; ++x) dst[x] = std::min(std::sqrt(src[x - wx0]), cap);
  }
}

}  // namespace rb
