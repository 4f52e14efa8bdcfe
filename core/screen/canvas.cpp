#include "screen/canvas.h"

#include <algorithm>
#include <cmath>
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

Canvas::Canvas() : pixels_(static_cast<size_t>(kWidth) * kHeight, colours::kWhite) {}

void Canvas::record(DrawOp op) {
  if (ops_.size() < kMaxDisplayOps) {
    ops_.push_back(std::move(op));
  } else if (ops_.back().kind != DrawOp::Raster) {
    ops_.push_back(DrawOp{DrawOp::Raster, {}});
  }
}

void Canvas::clear(Colour c) {
  bool changed = c != background_;
  background_ = c;
  std::fill(pixels_.begin(), pixels_.end(), c);
  if (changed) ++obstacleVersion_;
  ++obstacleVersion_;
  ++version_;
  cursor_ = {};
  ops_.clear();
  trailOpen_ = false;
  record(DrawOp{DrawOp::Clear, {}, c});
}

void Canvas::setInvisible(std::vector<Colour> c) {
  invisible_ = std::move(c);
  ++obstacleVersion_;
}

void Canvas::setPixel(int x, int y, Colour c) {
  plot(x, y, c);
  record(DrawOp{DrawOp::Pixel, {{x, y}}, c});
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

void Canvas::line(Point a, Point b, int width, Colour c) {
  // Bresenham, with the brush at every point.
  int x = a.x, y = a.y;
  int dx = std::abs(b.x - a.x), dy = -std::abs(b.y - a.y);
  int sx = a.x < b.x ? 1 : -1, sy = a.y < b.y ? 1 : -1;
  int err = dx + dy;
  // Lines far outside the screen are clipped to a generous box first, to bound the work.
  if (std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y)}) > 100000) {
    record(DrawOp{DrawOp::Line, {a, b}, c, std::nullopt, width});
    return;
  }
  for (;;) {
    brush(x, y, width, c);
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
  record(DrawOp{DrawOp::Line, {a, b}, c, std::nullopt, width});
}

void Canvas::span(int y, int x1, int x2, Colour c) {
  if (y < 0 || y >= kHeight) return;
  x1 = std::max(x1, 0);
  x2 = std::min(x2, kWidth - 1);
  for (int x = x1; x <= x2; ++x) plot(x, y, c);
}

void Canvas::rectangle(Point a, Point b, int width, std::optional<Colour> outline,
                       std::optional<Colour> fill) {
  int x1 = std::min(a.x, b.x), x2 = std::max(a.x, b.x);
  int y1 = std::min(a.y, b.y), y2 = std::max(a.y, b.y);
  x1 = std::max(x1, -1);
  y1 = std::max(y1, -1);
  x2 = std::min(x2, kWidth);
  y2 = std::min(y2, kHeight);
  if (fill)
    for (int y = y1; y <= y2; ++y) span(y, x1, x2, *fill);
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
  record(DrawOp{DrawOp::Rect, {{x1, y1}, {x2, y2}}, outline.value_or(0), fill, outline ? width : 0});
}

void Canvas::ellipse(Point a, Point b, int width, std::optional<Colour> outline,
                     std::optional<Colour> fill) {
  int x1 = std::min(a.x, b.x), x2 = std::max(a.x, b.x);
  int y1 = std::min(a.y, b.y), y2 = std::max(a.y, b.y);
  double cx = (x1 + x2) / 2.0, cy = (y1 + y2) / 2.0;
  double rx = (x2 - x1) / 2.0, ry = (y2 - y1) / 2.0;
  int w = std::max(width, 1);
  // A pixel is inside when its centre lies in the ellipse grown by half a pixel, so that a
  // box of zero width or height still draws a line. The outline is the ring of width w.
  auto inside = [](double dx, double dy, double ax, double ay) {
    double u = dx / (ax + 0.5), v = dy / (ay + 0.5);
    return u * u + v * v <= 1.0;
  };
  double irx = rx - w, iry = ry - w;
  bool hasInner = irx + 0.5 > 0 && iry + 0.5 > 0;
  int ylo = std::max(y1, 0), yhi = std::min(y2, kHeight - 1);
  int xlo = std::max(x1, 0), xhi = std::min(x2, kWidth - 1);
  for (int y = ylo; y <= yhi; ++y) {
    for (int x = xlo; x <= xhi; ++x) {
      double dx = x - cx, dy = y - cy;
      if (!inside(dx, dy, rx, ry)) continue;
      bool inner = hasInner && inside(dx, dy, irx, iry);
      if (outline && !inner) plot(x, y, *outline);
      else if (fill) plot(x, y, *fill);
    }
  }
  record(DrawOp{DrawOp::Ellipse, {{x1, y1}, {x2, y2}}, outline.value_or(0), fill, outline ? width : 0});
}

void Canvas::polygon(const std::vector<Point>& pts, int width, std::optional<Colour> outline,
                     std::optional<Colour> fill) {
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
    for (size_t i = 0; i < pts.size(); ++i) line(pts[i], pts[(i + 1) % pts.size()], width, *outline);
    ops_.erase(ops_.begin() + static_cast<long>(saved), ops_.end());  // recorded once, as the polygon
  }
  record(DrawOp{DrawOp::Polygon, pts, outline.value_or(0), fill, outline ? width : 0});
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
  record(DrawOp{DrawOp::Raster, {}});
}

FontRenderer& Canvas::fonts() {
  if (!fonts_) fonts_ = std::make_unique<FontRenderer>();
  return *fonts_;
}

int Canvas::text(int x, int y, const std::string& s, const TextStyle& style, Colour c) {
  FontRenderer& f = fonts();
  const FontMetrics m = f.metrics(style.font);
  const int width = f.width(style.font, s);
  if (style.background)
    for (int yy = 0; yy < m.lineHeight; ++yy) span(y + yy, x, x + width - 1, *style.background);
  const int baseline = y + m.ascent;
  int penX = x;
  for (unsigned char chr : s) {
    if (penX >= kWidth) break;  // the rest of the text is off the screen
    const Glyph& g = f.glyph(style.font, chr);
    const int left = penX + g.left, top = baseline - g.top;
    for (int gy = 0; gy < g.height; ++gy)
      for (int gx = 0; gx < g.width; ++gx)
        if (g.pixel(gx, gy)) plot(left + gx, top + gy, c);
    penX += g.advance;
  }
  if (style.underline)
    for (int k = 0; k < m.underlineThickness; ++k) span(y + m.underlineTop + k, x, x + width - 1, c);
  if (style.strikeout)
    for (int k = 0; k < m.strikeoutThickness; ++k) span(y + m.strikeoutTop + k, x, x + width - 1, c);
  DrawOp op{DrawOp::Text, {{x, y}, {x + width, y + m.lineHeight}}, c, std::nullopt, 1, s, style};
  op.ascent = m.ascent;
  record(std::move(op));
  return width;
}

void Canvas::scrollUp(int pixels) {
  size_t shift = static_cast<size_t>(pixels) * kWidth;
  std::move(pixels_.begin() + static_cast<long>(shift), pixels_.end(), pixels_.begin());
  std::fill(pixels_.end() - static_cast<long>(shift), pixels_.end(), background_);
  ++obstacleVersion_;
  ++version_;
  record(DrawOp{DrawOp::Raster, {}});
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

void Canvas::save() { saved_ = pixels_; }

void Canvas::restore() {
  if (saved_.empty()) return;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) plot(x, y, saved_[static_cast<size_t>(y) * kWidth + static_cast<size_t>(x)]);
  record(DrawOp{DrawOp::Raster, {}});
}

void Canvas::trailStart(double x, double y, int width, Colour c) {
  trailAt_ = {static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y))};
  trailWidth_ = width;
  trailColour_ = c;
  trailOpen_ = true;
  record(DrawOp{DrawOp::Trail, {trailAt_}, c, std::nullopt, width});
  trailOp_ = ops_.size() - 1;
}

void Canvas::trailTo(double x, double y) {
  Point to{static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y))};
  if (!trailOpen_ || to == trailAt_) return;
  // Draw the segment without recording it: it is part of the trail's polyline.
  size_t saved = ops_.size();
  line(trailAt_, to, trailWidth_, trailColour_);
  ops_.erase(ops_.begin() + static_cast<long>(saved), ops_.end());
  if (!ops_.empty() && trailOp_ == ops_.size() - 1 && ops_.back().kind == DrawOp::Trail) {
    ops_.back().points.push_back(to);
  } else {
    // Something was drawn since: the trail goes on from where it ended.
    record(DrawOp{DrawOp::Trail, {trailAt_, to}, trailColour_, std::nullopt, trailWidth_});
    trailOp_ = ops_.size() - 1;
  }
  trailAt_ = to;
}

}  // namespace rb
