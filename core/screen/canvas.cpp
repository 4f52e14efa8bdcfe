#include "screen/canvas.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <cstdint>
#include <cstdlib>

namespace rb {

namespace {
// RobotBASIC 4.2's colours. Confirmed by screenshots: Blue, Cyan, Red, Gray, LightRed. The
// others are rb's choice by the same pattern: a dark colour has each channel at 0, 128 or 255,
// its light twin (colour + 8) adds 128 to every channel, capped at 255; Brown and Yellow are the
// colours their names say. docs/graphics.md has the table.
constexpr uint32_t kPalette[16] = {
    0x000000,  //  0 Black
    0x0000FF,  //  1 Blue          confirmed
    0x008000,  //  2 Green
    0x008080,  //  3 Cyan          confirmed
    0xFF0000,  //  4 Red           confirmed
    0xFF00FF,  //  5 Magenta
    0x804000,  //  6 Brown
    0xC0C0C0,  //  7 Gray          confirmed
    0x808080,  //  8 DarkGray      = Black + 128
    0x8080FF,  //  9 LightBlue     = Blue + 128
    0x80FF80,  // 10 LightGreen    = Green + 128
    0x80FFFF,  // 11 LightCyan     = Cyan + 128
    0xFF8080,  // 12 LightRed      = Red + 128, confirmed
    0xFF80FF,  // 13 LightMagenta  = Magenta + 128
    0xFFFF00,  // 14 Yellow
    0xFFFFFF,  // 15 White         = Gray + 128, capped
};
constexpr int kTabColumns = 8;
constexpr size_t kMaxDisplayOps = 2'000'000;
}  // namespace

uint32_t colourToRgb(Colour c) {
  if (c < 16) return kPalette[c];
  uint32_t r = c & 0xff, g = (c >> 8) & 0xff, b = (c >> 16) & 0xff;
  return r << 16 | g << 8 | b;
}

Colour rgbColour(int r, int g, int b) {
  auto clamp = [](int v) { return static_cast<Colour>(std::clamp(v, 0, 255)); };
  return clamp(r) | clamp(g) << 8 | clamp(b) << 16;
}

PixelBox& ChangeBoxes::boxForFar(int x, int y) {
  for (PixelBox& b : boxes)
    if (x >= b.x0 - kJoin && x <= b.x1 + kJoin && y >= b.y0 - kJoin && y <= b.y1 + kJoin) return b;
  if (boxes.size() < kMaxBoxes) return boxes.emplace_back();
  // Too many scattered changes: one box holds them all.
  PixelBox merged;
  for (const PixelBox& b : boxes) merged.add(b);
  boxes.assign(1, merged);
  return boxes.back();
}

Canvas::Canvas() = default;

void Canvas::makePixels() const {
  pixels_.assign(static_cast<size_t>(kWidth) * kHeight, background_);
}

void Canvas::push(DrawOp op) {
  ++opsGeneration_;
  if (ops_.size() < kMaxDisplayOps) {
    ops_.push_back(std::move(op));
  } else if (ops_.back().kind != DrawOp::Raster) {
    ops_.push_back(DrawOp{DrawOp::Raster, {}});
  }
}

void Canvas::keepDisplayList(bool keep) {
  keepOps_ = keep;
  if (!keep) {
    ops_.clear();
    ops_.shrink_to_fit();
  }
}

void Canvas::clear(Colour c) {
  background_ = c;
  std::fill(pixels_.begin(), pixels_.end(), c);  // nothing to fill while the screen is unmade
  forgetAllTraces();
  obstaclesChangedEverywhere();
  ++version_;
  damageAll();
  cursor_ = {};
  ops_.clear();
  trailOpen_ = false;
  record([&] { return DrawOp{DrawOp::Clear, {}, c}; });
}

void Canvas::setInvisible(std::vector<Colour> c) {
  invisible_ = std::move(c);
  obstaclesChangedEverywhere();
}

void Canvas::setPixel(int x, int y, Colour c) {
  plot(x, y, c);
  record([&] { return DrawOp{DrawOp::Pixel, {{x, y}}, c}; });
}

// A round brush of diameter `width` centred on the pixel; width 1 is the pixel itself.
void Canvas::brush(int x, int y, int width, Colour c) {
  if (width <= 1) {
    plot(x, y, c);
    return;
  }
  int lo = -(width / 2), hi = (width - 1) / 2;
  double centre = width % 2 == 0 ? -0.5 : 0.0;
  double r2 = width * width / 4.0 + 1e-9;
  for (int dy = lo; dy <= hi; ++dy)
    for (int dx = lo; dx <= hi; ++dx) {
      double fx = dx - centre, fy = dy - centre;
      if (fx * fx + fy * fy <= r2) plot(x + dx, y + dy, c);
    }
}

namespace {
/// Clips the segment a-b to the box [lo, hi] in both coordinates (Liang-Barsky); false when
/// nothing of it is inside.
bool clipSegment(double& ax, double& ay, double& bx, double& by, double lo, double hiX, double hiY) {
  double t0 = 0, t1 = 1;
  const double dx = bx - ax, dy = by - ay;
  const double p[4] = {-dx, dx, -dy, dy};
  const double q[4] = {ax - lo, hiX - ax, ay - lo, hiY - ay};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0) {
      if (q[k] < 0) return false;
      continue;
    }
    double t = q[k] / p[k];
    if (p[k] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  bx = ax + t1 * dx, by = ay + t1 * dy;
  ax = ax + t0 * dx, ay = ay + t0 * dy;
  return true;
}
}  // namespace

void Canvas::drawLine(Point a, Point b, int width, Colour c) {
  // Only the part that can touch the screen is drawn: a line far outside it costs nothing, and
  // one crossing it from far away costs little more than one across the screen.
  const int margin = width / 2 + 2;
  double ax = a.x, ay = a.y, bx = b.x, by = b.y;
  if (!clipSegment(ax, ay, bx, by, -margin, kWidth - 1 + margin, kHeight - 1 + margin)) return;
  const auto near = [&](int x, int y) {
    return x >= -margin && y >= -margin && x <= kWidth - 1 + margin && y <= kHeight - 1 + margin;
  };
  // Bresenham from the true end points (so that a line is the same pixels however far its ends
  // lie), with the brush only near the screen. Lines longer than any clamped coordinate allows
  // start where they enter the screen instead.
  if (std::max(std::abs(int64_t(b.x) - a.x), std::abs(int64_t(b.y) - a.y)) > 4'000'000) {
    a = {static_cast<int>(std::lround(ax)), static_cast<int>(std::lround(ay))};
    b = {static_cast<int>(std::lround(bx)), static_cast<int>(std::lround(by))};
  }
  int x = a.x, y = a.y;
  int dx = std::abs(b.x - a.x), dy = -std::abs(b.y - a.y);
  int sx = a.x < b.x ? 1 : -1, sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  bool entered = false;
  for (;;) {
    if (near(x, y)) {
      brush(x, y, width, c);
      entered = true;
    } else if (entered) {
      break;  // a straight line that left the screen does not come back
    }
    if (x == b.x && y == b.y) break;
    int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      x += sx;
    }
    if (e2 <= dx) {
      err += dx;
      y += sy;
    }
  }
}

void Canvas::line(Point a, Point b, int width, Colour c) {
  drawLine(a, b, width, c);
  record([&] { return DrawOp{DrawOp::Line, {a, b}, c, std::nullopt, width}; });
}

void Canvas::span(int y, int x1, int x2, Colour c) {
  if (y < 0 || y >= kHeight) return;
  x1 = std::max(x1, 0);
  x2 = std::min(x2, kWidth - 1);
  if (x1 > x2) return;
  // plot() for each pixel, in passes that each do one simple thing: the first and the last
  // pixel that change, the first and the last that become or stop being an obstacle, then the
  // fill between (which the compiler turns into wide stores).
  Colour* row = &materialize()[static_cast<size_t>(y) * kWidth];
  int first = x1;
  while (first <= x2 && row[first] == c) ++first;
  if (first > x2) return;
  int last = x2;
  while (row[last] == c) --last;
  const bool obstacle = isObstacleColour(c);
  int firstFlip = -1, lastFlip = -1;  // ... that became or stopped being an obstacle
  if (!invisible_.empty()) {
    for (int x = first; x <= last; ++x) {
      if (row[x] != c && isObstacleColour(row[x]) != obstacle) {
        if (firstFlip < 0) firstFlip = x;
        lastFlip = x;
      }
    }
  } else if (!obstacle) {
    // c is the background: every pixel that changes was an obstacle.
    firstFlip = first;
    lastFlip = last;
  } else {
    // Only background pixels become obstacles.
    int x = first;
    while (x <= last && row[x] != background_) ++x;
    if (x <= last) {
      firstFlip = x;
      lastFlip = last;
      while (row[lastFlip] != background_) --lastFlip;
    }
  }
  std::fill(row + first, row + last + 1, c);
  rowChanged(y, first, last, firstFlip, lastFlip);
}

void Canvas::rowChanged(int y, int first, int last, int firstFlip, int lastFlip) {
  ++version_;
  if (tracking_) changed(y, first, last);
  if (firstFlip >= 0) {
    ++obstacleVersion_;
    obstacleChanges_.addRow(y, firstFlip, lastFlip);
  }
  if (liveTraces_ != 0) forgetTraces(y, first, last);
}

void Canvas::writeRow(int y, int x, const Colour* px, int n) {
  if (y < 0 || y >= kHeight) return;
  int from = std::max(0, -x), to = std::min(n, kWidth - x);  // px[from..to-1] are on the screen
  if (from >= to) return;
  Colour* row = &materialize()[static_cast<size_t>(y) * kWidth + static_cast<size_t>(x)];
  int first = -1, last = -1, firstFlip = -1, lastFlip = -1;
  for (int i = from; i < to; ++i) {
    if (row[i] == px[i]) continue;
    if (isObstacleColour(row[i]) != isObstacleColour(px[i])) {
      if (firstFlip < 0) firstFlip = x + i;
      lastFlip = x + i;
    }
    row[i] = px[i];
    if (first < 0) first = x + i;
    last = x + i;
  }
  if (first >= 0) rowChanged(y, first, last, firstFlip, lastFlip);
}

void Canvas::paintCell(int x0, int w, int y0, int h, Colour background, const Glyph& g, int left, int top,
                       Colour c) {
  constexpr int kMaxCell = 256;
  if (w > kMaxCell) {  // a character this wide: its background, then its glyph
    for (int yy = 0; yy < h; ++yy) span(y0 + yy, x0, x0 + w - 1, background);
    paintGlyph(g, left, top, c);
    return;
  }
  Colour cell[kMaxCell];
  for (int yy = 0; yy < h; ++yy) {
    std::fill(cell, cell + w, background);
    const int gy = y0 + yy - top;  // the glyph's bitmap row on this row of the cell
    if (gy >= 0 && gy < g.height) {
      const uint8_t* bits = &g.bits[static_cast<size_t>(gy) * static_cast<size_t>(g.width)];
      for (int gx = 0; gx < g.width; ++gx) {
        const int cx = left + gx - x0;
        if (bits[gx] && cx >= 0 && cx < w) cell[cx] = c;
      }
    }
    writeRow(y0 + yy, x0, cell, w);
  }
}

void Canvas::paintGlyph(const Glyph& g, int left, int top, Colour c) {
  if (left >= 0 && top >= 0 && left + g.width <= kWidth && top + g.height <= kHeight) {
    // On the screen: a run whose pixels all have the colour already (text drawn over itself)
    // is passed over without span()'s clipping and bookkeeping.
    const Colour* origin = &materialize()[static_cast<size_t>(top) * kWidth + static_cast<size_t>(left)];
    for (const Glyph::Run& r : g.runs) {
      const Colour* p = origin + static_cast<ptrdiff_t>(r.y) * kWidth + r.x;
      int k = 0;
      while (k < r.length && p[k] == c) ++k;
      if (k < r.length) span(top + r.y, left + r.x + k, left + r.x + r.length - 1, c);
    }
    return;
  }
  for (const Glyph::Run& r : g.runs) span(top + r.y, left + r.x, left + r.x + r.length - 1, c);
}

void Canvas::forgetTraces(int y, int x1, int x2) {
  for (TextTrace& t : traces_) {
    if (t.live && y >= t.box.y0 && y <= t.box.y1 && x2 >= t.box.x0 &&
        x1 <= t.box.x1) {
      t.live = false;
      --liveTraces_;
    }
  }
}

void Canvas::rectangle(Point a, Point b, int width, std::optional<Colour> outline,
                       std::optional<Colour> fill) {
  int x1 = std::min(a.x, b.x), x2 = std::max(a.x, b.x);
  int y1 = std::min(a.y, b.y), y2 = std::max(a.y, b.y);
  x1 = std::max(x1, -1);
  y1 = std::max(y1, -1);
  x2 = std::min(x2, kWidth);
  y2 = std::min(y2, kHeight);
  if (fill) {
    for (int y = y1; y <= y2; ++y) span(y, x1, x2, *fill);
    // A fill of the whole screen hides everything drawn before it.
    if (keepOps_ && x1 <= 0 && y1 <= 0 && x2 >= kWidth - 1 && y2 >= kHeight - 1) ops_.clear();
  }
  if (outline) {
    // The outline lies on the rectangle's edge, growing inward with the line width.
    int w = std::max(width, 1);
    for (int k = 0; k < w; ++k) {
      span(y1 + k, x1, x2, *outline);
      span(y2 - k, x1, x2, *outline);
      for (int y = y1; y <= y2; ++y) {
        plot(x1 + k, y, *outline);
        plot(x2 - k, y, *outline);
      }
    }
  }
  record([&] { return DrawOp{DrawOp::Rect, {{x1, y1}, {x2, y2}}, outline.value_or(0), fill, outline ? width : 0}; });
}

namespace {

/// The pixels of one row of an ellipse (see Canvas::ellipse): those whose centre lies in the
/// ellipse with half-axes ax + 0.5 and ay + 0.5 around (cx, cy), for the row dy below the
/// centre. The rule is the same test per pixel as ever; only the row's two ends are searched:
/// the test is symmetric about cx and grows with |dx|, so the row is one run of pixels.
struct EllipseRows {
  double cx, ax, ay;
  bool inside(double dx, double dy) const {
    double u = dx / (ax + 0.5), v = dy / (ay + 0.5);
    return u * u + v * v <= 1.0;
  }
  /// The row's last pixel right of the centre line, as a distance from the centre (>= 0, a
  /// whole or half number like cx's fraction); negative when the row is empty.
  double halfWidth(double dy) const {
    // The first pixel at or right of the centre.
    double first = std::ceil(cx) - cx;
    if (!inside(first, dy)) return -1;
    double v = dy / (ay + 0.5);
    double t = 1.0 - v * v;
    double guess = (ax + 0.5) * std::sqrt(t > 0 ? t : 0.0);
    double d = first + std::floor(guess - first);
    if (d < first) d = first;
    // The square root is within a pixel of the answer; the per-pixel test settles it.
    while (d > first && !inside(d, dy)) d -= 1;
    while (inside(d + 1, dy)) d += 1;
    return d;
  }
};

}  // namespace

void Canvas::ellipse(Point a, Point b, int width, std::optional<Colour> outline,
                     std::optional<Colour> fill) {
  int x1 = std::min(a.x, b.x), x2 = std::max(a.x, b.x);
  int y1 = std::min(a.y, b.y), y2 = std::max(a.y, b.y);
  double cx = (x1 + x2) / 2.0, cy = (y1 + y2) / 2.0;
  double rx = (x2 - x1) / 2.0, ry = (y2 - y1) / 2.0;
  int w = std::max(width, 1);
  // A pixel is inside when its centre lies in the ellipse grown by half a pixel, so that a
  // box of zero width or height still draws a line. The outline is the ring of width w: the
  // pixels inside the ellipse and not inside the one w pixels smaller.
  double irx = rx - w, iry = ry - w;
  bool hasInner = irx + 0.5 > 0 && iry + 0.5 > 0;
  const EllipseRows outer{cx, rx, ry}, inner{cx, irx, iry};
  int ylo = std::max(y1, 0), yhi = std::min(y2, kHeight - 1);
  // Row ends in doubles: the box may be far larger than the screen.
  auto draw = [&](int y, double from, double to, Colour c) {
    from = std::max(from, static_cast<double>(std::max(x1, 0)));
    to = std::min(to, static_cast<double>(std::min(x2, kWidth - 1)));
    if (from <= to) span(y, static_cast<int>(from), static_cast<int>(to), c);
  };
  for (int y = ylo; y <= yhi; ++y) {
    double dy = y - cy;
    double h = outer.halfWidth(dy);
    if (h < 0) continue;
    double left = cx - h, right = cx + h;
    double ih = hasInner ? inner.halfWidth(dy) : -1;
    if (!outline) {
      if (fill) draw(y, left, right, *fill);
      continue;
    }
    if (ih < 0) {
      draw(y, left, right, *outline);
      continue;
    }
    draw(y, left, cx - ih - 1, *outline);
    draw(y, cx + ih + 1, right, *outline);
    if (fill) draw(y, cx - ih, cx + ih, *fill);
  }
  record([&] { return DrawOp{DrawOp::Ellipse, {{x1, y1}, {x2, y2}}, outline.value_or(0), fill, outline ? width : 0}; });
}

void Canvas::polygon(const std::vector<Point>& pts, int width, std::optional<Colour> outline,
                     std::optional<Colour> fill, const std::function<void()>& afterEdge) {
  if (pts.empty()) return;
  if (fill && pts.size() >= 3) {
    // Even-odd scanline fill through pixel centres.
    int ylo = pts[0].y, yhi = pts[0].y;
    for (const Point& p : pts) {
      ylo = std::min(ylo, p.y);
      yhi = std::max(yhi, p.y);
    }
    ylo = std::max(ylo, 0);
    yhi = std::min(yhi, kHeight - 1);
    std::vector<double> xs;
    for (int y = ylo; y <= yhi; ++y) {
      xs.clear();
      double sy = y + 0.5;
      for (size_t i = 0; i < pts.size(); ++i) {
        const Point& p = pts[i];
        const Point& q = pts[(i + 1) % pts.size()];
        if ((p.y + 0.5 <= sy) != (q.y + 0.5 <= sy)) {
          double t = (sy - (p.y + 0.5)) / (q.y - p.y);
          xs.push_back(p.x + t * (q.x - p.x));
        }
      }
      std::sort(xs.begin(), xs.end());
      for (size_t i = 0; i + 1 < xs.size(); i += 2)
        span(y, static_cast<int>(std::ceil(xs[i] - 0.5)), static_cast<int>(std::floor(xs[i + 1] - 0.5)), *fill);
    }
  }
  if (outline) {
    auto saved = ops_.size();
    for (size_t i = 0; i < pts.size(); ++i) {
      line(pts[i], pts[(i + 1) % pts.size()], width, *outline);
      if (afterEdge) afterEdge();
    }
    ops_.erase(ops_.begin() + static_cast<long>(saved), ops_.end());  // recorded once, as the polygon
  }
  record([&] { return DrawOp{DrawOp::Polygon, pts, outline.value_or(0), fill, outline ? width : 0}; });
}

void Canvas::floodFill(int x, int y, Colour c) {
  if (!inside(x, y)) return;
  Colour target = at(x, y);
  if (target == c) return;
  std::vector<Point> stack{{x, y}};
  while (!stack.empty()) {
    Point p = stack.back();
    stack.pop_back();
    if (!inside(p.x, p.y) || at(p.x, p.y) != target) continue;
    // Fill the whole run on this row, then look above and below it.
    int l = p.x, r = p.x;
    while (l > 0 && at(l - 1, p.y) == target) --l;
    while (r < kWidth - 1 && at(r + 1, p.y) == target) ++r;
    for (int i = l; i <= r; ++i) plot(i, p.y, c);
    for (int ny : {p.y - 1, p.y + 1}) {
      if (ny < 0 || ny >= kHeight) continue;
      for (int i = l; i <= r; ++i)
        if (at(i, ny) == target && (i == l || at(i - 1, ny) != target)) stack.push_back({i, ny});
    }
  }
  record([&] { return DrawOp{DrawOp::Raster, {}}; });
}

FontRenderer& Canvas::fonts() {
  if (!fonts_) fonts_ = std::make_unique<FontRenderer>();
  return *fonts_;
}

namespace {

bool sameTextStyle(const TextStyle& a, const TextStyle& b) {
  return a.font == b.font && a.underline == b.underline && a.strikeout == b.strikeout &&
         a.background == b.background;
}

}  // namespace

int Canvas::text(int x, int y, const std::string& s, const TextStyle& style, Colour c) {
  FontRenderer& f = fonts();
  const FontMetrics& m = f.metrics(style.font);
  // A text longer than kMaxTraceChars is drawn without the memory below (its glyphs looked
  // up one by one past that length): a long string costs no memory in proportion to its length.
  std::vector<const Glyph*>& glyphs = glyphScratch_;
  const int width = f.glyphs(style.font, s, glyphs, kMaxTraceChars);

  // The same text style drawn at the same place before, its pixels untouched since: its
  // characters that are drawn again where they already are can be left alone. With a
  // background, each changed character's cell is painted afresh, which is the same picture
  // only when no glyph, old or new, reaches into a neighbouring cell.
  TextTrace* trace = nullptr;
  bool reuse = false;
  if (textMemory_ && s.size() <= kMaxTraceChars) {
    for (TextTrace& t : traces_)
      if (t.live && t.at == Point{x, y} && t.colour == c && sameTextStyle(t.style, style)) {
        trace = &t;
        reuse = !style.background ||
                (t.inCells && std::all_of(glyphs.begin(), glyphs.end(), [](const Glyph* g) { return g->inCell; }));
        break;
      }
    if (!trace) {  // a free slot, else the oldest
      trace = &traces_[0];
      for (TextTrace& t : traces_) {
        if (!t.live) {
          trace = &t;
          break;
        }
        if (t.drawn < trace->drawn) trace = &t;
      }
    }
    if (trace->live) --liveTraces_;
    trace->live = false;  // so that this draw's own pixels do not forget it
  }
  const size_t before = reuse ? trace->text.size() : 0;  // characters drawn last time
  if (trace) {
    trace->text.resize(s.size());
    trace->pens.resize(s.size());
  }

  // The background behind the cells from x1 to x2.
  auto background = [&](int x1, int x2) {
    for (int yy = 0; yy < m.lineHeight; ++yy) span(y + yy, x1, x2, *style.background);
  };
  if (style.background && !reuse) background(x, x + width - 1);
  const int baseline = y + m.ascent;
  PixelBox box;  // where this draw may have painted: the cells, and glyphs reaching out of them
  bool inCells = true;
  int penX = x;
  size_t drawn = 0;
  if (before > 0 && trace->inCells) {
    // The characters before the first that changed are already there, at the same places
    // (same font, same characters before them), each inside its own cell.
    const size_t n = std::min(before, s.size());
    drawn = static_cast<size_t>(std::mismatch(s.begin(), s.begin() + static_cast<long>(n), trace->text.begin()).first - s.begin());
    if (drawn > 0) penX = drawn < before ? trace->pens[drawn] : trace->pens[drawn - 1] + glyphs[drawn - 1]->advance;
  }
  for (; drawn < s.size() && penX < kWidth; ++drawn) {  // the rest would be off the screen
    const Glyph& g = drawn < glyphs.size() ? *glyphs[drawn] : f.glyph(style.font, static_cast<unsigned char>(s[drawn]));
    const int left = penX + g.left, top = baseline - g.top;
    if (trace) {
      const bool same = drawn < before && trace->text[drawn] == s[drawn] && trace->pens[drawn] == penX;
      trace->text[drawn] = s[drawn];
      trace->pens[drawn] = penX;
      if (!g.inCell) {
        inCells = false;
        box.add(left, top);
        box.add(left + g.width - 1, top + g.height - 1);
      }
      if (same) {
        penX += g.advance;
        continue;  // already there
      }
      if (style.background && reuse) {  // the glyph lies inside its cell (reuse)
        paintCell(penX, g.advance, y, m.lineHeight, *style.background, g, left, top, c);
        penX += g.advance;
        continue;
      }
    }
    paintGlyph(g, left, top, c);
    penX += g.advance;
  }
  if (style.underline)
    for (int k = 0; k < m.underlineThickness; ++k) span(y + m.underlineTop + k, x, x + width - 1, c);
  if (style.strikeout)
    for (int k = 0; k < m.strikeoutThickness; ++k) span(y + m.strikeoutTop + k, x, x + width - 1, c);

  if (trace && drawn > 0) {
    box.add(x, y);
    box.add(x + std::max(width, 1) - 1, y + m.lineHeight - 1);
    if (style.underline) box.add(x, y + m.underlineTop + m.underlineThickness - 1);
    if (style.strikeout) box.add(x, y + m.strikeoutTop + m.strikeoutThickness - 1);
    trace->text.resize(drawn);
    trace->pens.resize(drawn);
    trace->live = true;
    ++liveTraces_;
    trace->at = {x, y};
    trace->style = style;
    trace->colour = c;
    trace->box = box;
    trace->inCells = inCells;
    trace->drawn = ++textClock_;
  }
  record([&] {
    DrawOp op{DrawOp::Text, {{x, y}, {x + width, y + m.lineHeight}}, c, std::nullopt, 1, s, style};
    op.ascent = m.ascent;
    return op;
  });
  return width;
}

void Canvas::scrollUp(int pixels) {
  size_t shift = static_cast<size_t>(pixels) * kWidth;
  materialize();
  std::move(pixels_.begin() + static_cast<long>(shift), pixels_.end(), pixels_.begin());
  std::fill(pixels_.end() - static_cast<long>(shift), pixels_.end(), background_);
  forgetAllTraces();
  obstaclesChangedEverywhere();
  ++version_;
  damageAll();
  record([&] { return DrawOp{DrawOp::Raster, {}}; });
}

namespace {

/// Lays out `text` from index `from` the way print does, starting at `cursor` (in pixels):
/// runs of characters wrap at the right edge, a tab moves to the next multiple of 8 columns,
/// '\r' goes back to the left edge. Calls `run(start, length, x, y)` for each run of characters
/// and `feed(nextIndex)` at each line end; `feed` moves the cursor down (and may scroll).
template <typename Run, typename Feed>
void layoutText(const std::string& text, size_t from, Point& cursor, int cw, Run run, Feed feed) {
  size_t runStart = from, runLength = 0;
  auto flush = [&] {
    if (runLength == 0) return;
    run(runStart, runLength, cursor.x, cursor.y);
    cursor.x += static_cast<int>(runLength) * cw;
    runLength = 0;
  };
  for (size_t i = from; i < text.size(); ++i) {
    char c = text[i];
    if (c == '\n') {
      flush();
      feed(i + 1);
    } else if (c == '\t') {
      flush();
      int col = cursor.x / cw;
      cursor.x = (col / kTabColumns + 1) * kTabColumns * cw;
      if (cursor.x >= Canvas::kWidth) feed(i + 1);
    } else if (c == '\r') {
      flush();
      cursor.x = 0;
    } else {
      if (cursor.x + (static_cast<int>(runLength) + 1) * cw > Canvas::kWidth) {
        flush();
        feed(i);
      }
      if (runLength == 0) runStart = i;
      ++runLength;
    }
  }
  flush();
}

}  // namespace

void Canvas::print(const std::string& s, bool newline) {
  TextStyle style;
  style.background = textBackground;
  const int cw = std::max(1, fonts().glyph(style.font, 'M').advance);
  const int ch = fonts().metrics(style.font).lineHeight;
  std::string all = newline ? s + "\n" : s;

  // A dry run first: where each line starts, and how far the screen would scroll.
  std::vector<size_t> lineStarts;
  long scroll = 0;
  Point dry = cursor_;
  layoutText(all, 0, dry, cw, [](size_t, size_t, int, int) {}, [&](size_t next) {
    lineStarts.push_back(next);
    dry.x = 0;
    dry.y += ch;
    if (dry.y + ch > kHeight) {
      scroll += dry.y + ch - kHeight;
      dry.y = kHeight - ch;
    }
  });

  size_t from = 0;
  if (scroll >= kHeight) {
    // Everything on the screen now would scroll away, line by line (a huge print would take
    // minutes): draw only the lines that stay visible, where scrolling would leave them.
    scrollUp(kHeight);
    long lines = static_cast<long>(lineStarts.size());
    long first = std::max(0L, lines - (kHeight - 1) / ch);
    cursor_.y = (kHeight - ch) - ch * static_cast<int>(lines - first);
    if (first > 0) {
      from = lineStarts[static_cast<size_t>(first - 1)];
      cursor_.x = 0;
    }
  }
  layoutText(
      all, from, cursor_, cw,
      [&](size_t start, size_t length, int x, int y) {
        text(x, y, all.substr(start, length), style, foreground);
      },
      [&](size_t) {
        cursor_.x = 0;
        cursor_.y += ch;
        if (cursor_.y + ch > kHeight) {
          scrollUp(cursor_.y + ch - kHeight);
          cursor_.y = kHeight - ch;
        }
      });
}

void Canvas::save() { saved_ = materialize(); }

void Canvas::restore() {
  if (saved_.empty()) return;
  forgetAllTraces();
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) plot(x, y, saved_[static_cast<size_t>(y) * kWidth + static_cast<size_t>(x)]);
  record([&] { return DrawOp{DrawOp::Raster, {}}; });
}

void Canvas::trailStart(double x, double y, int width, Colour c) {
  trailAt_ = {static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y))};
  trailOpen_ = true;
  trailEnd_ = {x, y};
  if (!keepOps_) {
    trailWidth_ = width;
    trailColour_ = c;
    return;
  }
  // The pen went down again (or the robot was placed) in the same colour and width with nothing
  // else drawn since the last trail entry: its segments still count as drawn.
  const bool keepSeen = trailSeenCurrent() && c == trailColour_ && width == trailWidth_;
  if (keepSeen && settleTrailSegment() && ops_.back().points.size() < 2) ops_.pop_back();
  trailColour_ = c;
  trailWidth_ = width;
  pushTrail({trailAt_}, keepSeen);
  trailAnchor_ = trailEnd_;
  trailCone_ = false;
}

void Canvas::pushTrail(std::vector<Point> pts, bool keepSeen) {
  push(DrawOp{DrawOp::Trail, std::move(pts), trailColour_, std::nullopt, trailWidth_});
  trailOp_ = ops_.size() - 1;
  if (!keepSeen) trailSeen_.clear();
  trailSeenGeneration_ = opsGeneration_;
}

bool Canvas::settleTrailSegment() {
  std::vector<Point>& pts = ops_.back().points;
  if (pts.size() < 2) return false;
  if (trailSeen_.insert(Segment{pts[pts.size() - 2], pts.back()}).second) return false;
  // Drawn before in this colour and width, and nothing drawn since could have covered it: a
  // polyline with round caps and joins covers exactly the union of its segments' round-capped
  // strokes, so leaving this one out changes nothing in the picture.
  pts.pop_back();
  return true;
}

namespace {
/// The angle b - a, in (-pi, pi].
double angleDiff(double a, double b) {
  double d = std::remainder(b - a, 2 * std::numbers::pi);
  return d;
}
}  // namespace

void Canvas::trailTo(double x, double y) {
  Point to{static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y))};
  if (!trailOpen_ || to == trailAt_) return;
  drawLine(trailAt_, to, trailWidth_, trailColour_);
  const Point from = trailAt_;
  const std::array<double, 2> fromExact = trailEnd_;
  trailAt_ = to;
  trailEnd_ = {x, y};
  if (!keepOps_) return;
  if (ops_.empty() || trailOp_ != ops_.size() - 1 || ops_.back().kind != DrawOp::Trail) {
    // Something was drawn since: the trail goes on from where it ended, in a new entry.
    pushTrail({from, to}, false);
    trailAnchor_ = fromExact;
    trailCone_ = false;
  }
  std::vector<Point>& pts = ops_.back().points;
  if (pts.size() == 1) {
    pts.push_back(to);
    trailCone_ = false;
  }
  // A straight stretch stays one segment: the end point moves on as long as every point it
  // passed lies within kTrailTolerance of the line from the last corner (the directions from
  // the corner that keep all of them so close form a cone that narrows as the trail goes on).
  const double dx = x - trailAnchor_[0], dy = y - trailAnchor_[1];
  const double d = std::hypot(dx, dy);
  const double dir = std::atan2(dy, dx);
  const double spread = d <= kTrailTolerance ? std::numbers::pi : std::asin(kTrailTolerance / d);
  if (trailCone_) {
    double off = angleDiff(trailConeDir_, dir);
    if (off >= trailConeLo_ && off <= trailConeHi_) {
      pts.back() = to;
      trailConeLo_ = std::max(trailConeLo_, off - spread);
      trailConeHi_ = std::min(trailConeHi_, off + spread);
      return;
    }
    // Out of the cone: the last point becomes a corner, and the segment before it is final.
    if (!settleTrailSegment()) {
      pts.push_back(to);
    } else if (pts.size() >= 2) {
      pushTrail({from, to}, true);  // a retraced segment left out: the trail goes on apart
    } else {
      pts = {from, to};
    }
    trailAnchor_ = fromExact;
    const double ndx = x - fromExact[0], ndy = y - fromExact[1];
    const double nd = std::hypot(ndx, ndy);
    trailConeDir_ = std::atan2(ndy, ndx);
    const double nspread = nd <= kTrailTolerance ? std::numbers::pi : std::asin(kTrailTolerance / nd);
    trailConeLo_ = -nspread, trailConeHi_ = nspread;
    return;
  }
  if (pts.size() >= 2) pts.back() = to;
  trailCone_ = true;
  trailConeDir_ = dir;
  trailConeLo_ = -spread, trailConeHi_ = spread;
}

}  // namespace rb
