#include "colour_watch.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace rb::record {

namespace {

/// A change of at most this many pixels is read at once; a larger one marks its cells unread.
constexpr long kReadAtOnce = 4096;
/// Unread cells this far beyond the robot's radius are read by a search, and kReadBudget more
/// (the nearest first); farther ones only end the clear disc. So the screen is read where the
/// robot goes, a little at a time: a program that clears the screen before every move makes
/// each search read a few thousand pixels, not all of them.
constexpr double kReadReach = 8;
constexpr int kReadBudget = 128;
/// How far beyond the radius a search looks: from kMinReach, doubling while nothing is found,
/// up to kMaxReach; after a find, twice the room that find left.
constexpr double kMinReach = 16, kMaxReach = 256;
/// What a point's disc must keep clear of the clear disc's edge: far more than the rounding of
/// any distance here, far less than a pixel.
constexpr double kSlack = 1e-6;

/// The squared distance between two points.
double distance2(P2 a, P2 b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }

/// The squared distance from `c` to the nearest point of the box x0..x1, y0..y1.
double boxDistance2(P2 c, double x0, double y0, double x1, double y1) {
  const double dx = std::max({x0 - c.x, 0.0, c.x - x1}), dy = std::max({y0 - c.y, 0.0, c.y - y1});
  return dx * dx + dy * dy;
}

}  // namespace

ColourWatch::ColourWatch(Canvas& canvas, const std::vector<uint32_t>& colours) : canvas_(canvas) {
  for (uint32_t rgb : colours) {
    size_t i = 0;
    while (i < watched_.size() && watched_[i].rgb != rgb) ++i;
    if (i == watched_.size()) {
      Watched& w = watched_.emplace_back();
      w.rgb = rgb;
      w.bits.assign(static_cast<size_t>(kCellsX) * kCellsY, 0);
      w.inBlock.assign(static_cast<size_t>(kBlocksX) * kBlocksY, 0);
      w.reach = kMinReach;
    }
    watchedOf_.push_back(i);
    touches_.push_back({rgb, false, {}, 0});
  }
  active_ = watched_.size();
  lastIndex_ = watched_.size();
  cellBits_.resize(watched_.size());
  unread_.assign(static_cast<size_t>(kCellsX) * kCellsY, 0);
  unreadInBlock_.assign(static_cast<size_t>(kBlocksX) * kBlocksY, 0);
  markAllUnread();
  if (active_ > 0) {
    canvas_.trackChanges(true);
    canvas_.takeChanges(changes_);  // everything: every cell is unread already
    seenVersion_ = canvas_.version();
  }
}

ColourWatch::~ColourWatch() {
  if (active_ > 0) canvas_.trackChanges(false);
}

void ColourWatch::startAt(P2 p) {
  last_ = p;
  placed_ = true;
}

void ColourWatch::robotEvent(const RobotEvent& e, double radius) {
  if (e.kind != RobotEvent::Locate && e.kind != RobotEvent::Move && e.kind != RobotEvent::Crash) return;
  P2 to{e.pose.pos.x(), e.pose.pos.y()};
  P2 from = e.kind == RobotEvent::Locate || !placed_ ? to : last_;
  last_ = to;
  placed_ = true;
  // The robot's own trail under it is not something it touched.
  std::optional<uint32_t> own;
  if (e.pen) own = colourToRgb(canvas_.trailColour());
  sweep(from, to, radius, own, e.loc.file == 0 ? e.loc.line : 0);
}

void ColourWatch::sweep(P2 from, P2 to, double radius, std::optional<uint32_t> ownRgb, uint32_t line) {
  if (active_ == 0) return;
  takeChanges();
  int n = 0;  // the points are 0..n (worked out when needed)
  for (size_t i = 0; i < watched_.size(); ++i) {
    Watched& w = watched_[i];
    if (w.done || (ownRgb && *ownRgb == w.rgb)) continue;
    // Both ends' discs inside the clear disc: so is every point's between them.
    const double room = w.clear - radius - kSlack;
    if (room > 0 && distance2(from, w.at) < room * room && distance2(to, w.at) < room * room) continue;
    if (n == 0) n = std::max(1, static_cast<int>(std::ceil(distance(from, to))));
    const long k = firstCover(w, from, to, n, radius);
    if (k < 0) continue;
    const double t = static_cast<double>(k) / n;
    const P2 c{from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t};
    w.done = true;
    --active_;
    for (size_t j = 0; j < touches_.size(); ++j)
      if (watchedOf_[j] == i) touches_[j] = {w.rgb, true, c, line};
  }
  if (active_ == 0) {
    // Nothing left to watch: the screen need not keep its changes any longer.
    canvas_.trackChanges(false);
    watched_.clear();
    watched_.shrink_to_fit();
  }
}

long ColourWatch::firstCover(Watched& w, P2 from, P2 to, int n, double radius) {
  const double step = distance(from, to) / n;  // between two points
  const double r2 = radius * radius;
  for (long k = 0; k <= n;) {
    const double t = static_cast<double>(k) / n;
    const P2 c{from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t};
    const double room = w.clear - radius - kSlack - std::sqrt(distance2(c, w.at));
    if (room > 0) {
      // This point's disc is inside the clear disc, and so is that of every point less than
      // `room` farther on.
      if (step <= 0) return -1;
      k += 1 + static_cast<long>(std::min(room / step, static_cast<double>(n)));
      continue;
    }
    const double d2 = nearest(w, c, radius);
    if (d2 <= r2) return k;
    w.at = c;
    w.clear = std::sqrt(d2);
    ++k;
  }
  return -1;
}

double ColourWatch::nearest(Watched& w, P2 c, double radius) {
  ++searches_;
  const double reach = radius + w.reach;
  double best = reach * reach;
  const double readBound = (radius + kReadReach) * (radius + kReadReach);
  int budget = kReadBudget;
  // The blocks within reach, nearest first.
  constexpr int kBlockPx = kBlock * kCell;
  const int bx0 = std::max(0, static_cast<int>(std::floor((c.x - reach) / kBlockPx)));
  const int by0 = std::max(0, static_cast<int>(std::floor((c.y - reach) / kBlockPx)));
  const int bx1 = std::min(kBlocksX - 1, static_cast<int>(std::floor((c.x + reach) / kBlockPx)));
  const int by1 = std::min(kBlocksY - 1, static_cast<int>(std::floor((c.y + reach) / kBlockPx)));
  near_.clear();
  for (int by = by0; by <= by1; ++by)
    for (int bx = bx0; bx <= bx1; ++bx) {
      const int b = by * kBlocksX + bx;
      if (w.inBlock[static_cast<size_t>(b)] == 0 && unreadInBlock_[static_cast<size_t>(b)] == 0) continue;
      const double d2 = boxDistance2(c, bx * kBlockPx, by * kBlockPx, bx * kBlockPx + kBlockPx - 1,
                                     by * kBlockPx + kBlockPx - 1);
      if (d2 < best) near_.push_back({d2, b});
    }
  std::sort(near_.begin(), near_.end(), [](const Near& a, const Near& b) { return a.d2 < b.d2; });
  const int fx = static_cast<int>(std::floor(c.x));
  for (const Near& nb : near_) {
    if (nb.d2 >= best) break;
    const int bx = nb.block % kBlocksX, by = nb.block / kBlocksX;
    const int cy1 = std::min(kCellsY, (by + 1) * kBlock), cx1 = std::min(kCellsX, (bx + 1) * kBlock);
    for (int cy = by * kBlock; cy < cy1; ++cy)
      for (int cx = bx * kBlock; cx < cx1; ++cx) {
        const int cell = cy * kCellsX + cx;
        const int x0 = cx * kCell, y0 = cy * kCell;
        const double cd2 = boxDistance2(c, x0, y0, x0 + kCell - 1, y0 + kCell - 1);
        if (cd2 >= best) continue;
        if (unread_[static_cast<size_t>(cell)]) {
          if (cd2 >= readBound && budget-- <= 0) {  // not read now: the clear disc ends there
            best = cd2;
            continue;
          }
          readCell(cell);
        }
        const uint64_t bits = w.bits[static_cast<size_t>(cell)];
        if (bits == 0) continue;
        // Each row of the cell: its nearest pixels of the colour left and right of c.x.
        const int col = fx - x0;  // c.x's column in the cell (may lie outside it)
        for (int row = 0; row < kCell; ++row) {
          const uint32_t b = static_cast<uint32_t>(bits >> (row * kCell)) & 0xffu;
          if (b == 0) continue;
          const int y = y0 + row;
          const double dy = y - c.y;
          if (dy * dy >= best) continue;
          uint32_t left = 0, right = b;  // the pixels at columns <= col, and those after
          if (col >= kCell - 1) {
            left = b, right = 0;
          } else if (col >= 0) {
            const uint32_t upTo = (2u << col) - 1;
            left = b & upTo, right = b & ~upTo;
          }
          if (left) best = std::min(best, coverDistance2(x0 + 31 - std::countl_zero(left), y, c));
          if (right) best = std::min(best, coverDistance2(x0 + std::countr_zero(right), y, c));
        }
      }
  }
  // The next search looks about twice as far as the room this one found, or farther when it
  // found nothing.
  if (best >= reach * reach) w.reach = std::min(kMaxReach, w.reach * 2);
  else w.reach = std::clamp(2 * (std::sqrt(best) - radius), kMinReach, kMaxReach);
  return best;
}

void ColourWatch::takeChanges() {
  if (canvas_.version() == seenVersion_) return;  // not a pixel changed
  seenVersion_ = canvas_.version();
  canvas_.takeChanges(changes_);
  if (changes_.all) {
    markAllUnread();
    return;
  }
  for (const PixelBox& changed : changes_.boxes) {
    PixelBox box;
    box.x0 = std::max(changed.x0, 0), box.y0 = std::max(changed.y0, 0);
    box.x1 = std::min(changed.x1, Canvas::kWidth - 1), box.y1 = std::min(changed.y1, Canvas::kHeight - 1);
    if (box.empty()) continue;
    if (box.area() <= kReadAtOnce) readPixels(box);
    else markUnread(box);
  }
}

void ColourWatch::readPixels(const PixelBox& box) {
  const Pixels& pixels = canvas_.pixels();
  for (int y = box.y0; y <= box.y1; ++y) {
    const Colour* row = pixels.data() + static_cast<size_t>(y) * Canvas::kWidth;
    for (int x = box.x0; x <= box.x1; ++x) {
      const size_t cell = static_cast<size_t>(y / kCell) * kCellsX + static_cast<size_t>(x / kCell);
      if (unread_[cell]) continue;  // read in full when needed
      const size_t now = indexOf(row[x]);
      const uint64_t bit = uint64_t{1} << ((y % kCell) * kCell + x % kCell);
      const size_t block = static_cast<size_t>(y / (kCell * kBlock)) * kBlocksX + static_cast<size_t>(x / (kCell * kBlock));
      for (size_t i = 0; i < watched_.size(); ++i) {
        Watched& w = watched_[i];
        if (w.done) continue;
        const bool want = now == i, has = (w.bits[cell] & bit) != 0;
        if (want == has) continue;
        w.bits[cell] ^= bit;
        if (has) {
          --w.inBlock[block];
          continue;
        }
        ++w.inBlock[block];
        // A new pixel of the colour inside the clear disc ends the disc there.
        const double d = std::sqrt(coverDistance2(x, y, w.at));
        if (d < w.clear) w.clear = d;
      }
    }
  }
}

void ColourWatch::markUnread(const PixelBox& box) {
  const int cx0 = box.x0 / kCell, cy0 = box.y0 / kCell, cx1 = box.x1 / kCell, cy1 = box.y1 / kCell;
  for (int cy = cy0; cy <= cy1; ++cy)
    for (int cx = cx0; cx <= cx1; ++cx) {
      const size_t cell = static_cast<size_t>(cy) * kCellsX + static_cast<size_t>(cx);
      if (unread_[cell]) continue;
      unread_[cell] = 1;
      const size_t block = static_cast<size_t>(cy / kBlock) * kBlocksX + static_cast<size_t>(cx / kBlock);
      ++unreadInBlock_[block];
      for (Watched& w : watched_) {
        if (w.done) continue;
        w.inBlock[block] = static_cast<uint16_t>(w.inBlock[block] - std::popcount(w.bits[cell]));
        w.bits[cell] = 0;
      }
    }
  // No clear disc reaches into an unread cell.
  for (Watched& w : watched_) {
    if (w.done) continue;
    const double d2 = boxDistance2(w.at, cx0 * kCell, cy0 * kCell, cx1 * kCell + kCell - 1, cy1 * kCell + kCell - 1);
    w.clear = std::min(w.clear, std::sqrt(d2));
  }
}

void ColourWatch::markAllUnread() {
  std::fill(unread_.begin(), unread_.end(), uint8_t{1});
  for (int by = 0; by < kBlocksY; ++by)
    for (int bx = 0; bx < kBlocksX; ++bx) {
      const int w = std::min(kCellsX, (bx + 1) * kBlock) - bx * kBlock;
      const int h = std::min(kCellsY, (by + 1) * kBlock) - by * kBlock;
      unreadInBlock_[static_cast<size_t>(by * kBlocksX + bx)] = static_cast<uint16_t>(w * h);
    }
  for (Watched& w : watched_) {
    std::fill(w.bits.begin(), w.bits.end(), uint64_t{0});
    std::fill(w.inBlock.begin(), w.inBlock.end(), uint16_t{0});
    w.clear = 0;
  }
}

void ColourWatch::readCell(int cell) {
  ++cellsRead_;
  const Pixels& pixels = canvas_.pixels();
  const int x0 = (cell % kCellsX) * kCell, y0 = (cell / kCellsX) * kCell;
  std::fill(cellBits_.begin(), cellBits_.end(), uint64_t{0});
  for (int row = 0; row < kCell; ++row) {
    const Colour* px = pixels.data() + static_cast<size_t>(y0 + row) * Canvas::kWidth + static_cast<size_t>(x0);
    for (int col = 0; col < kCell; ++col) {
      const size_t i = indexOf(px[col]);
      if (i < watched_.size()) cellBits_[i] |= uint64_t{1} << (row * kCell + col);
    }
  }
  const size_t block = static_cast<size_t>(y0 / (kCell * kBlock)) * kBlocksX + static_cast<size_t>(x0 / (kCell * kBlock));
  for (size_t i = 0; i < watched_.size(); ++i) {
    Watched& w = watched_[i];
    if (w.done) continue;
    w.bits[static_cast<size_t>(cell)] = cellBits_[i];
    w.inBlock[block] = static_cast<uint16_t>(w.inBlock[block] + std::popcount(cellBits_[i]));
  }
  unread_[static_cast<size_t>(cell)] = 0;
  --unreadInBlock_[block];
}

}  // namespace rb::record
