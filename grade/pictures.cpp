#include "pictures.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string_view>
#include <unordered_set>

#include "screen/font.h"
#include "text.h"

namespace rb::grade {

using record::P2;
using record::Polyline;
using record::Polylines;
using record::Region;
using record::distance;
using record::distanceToSegment;
using record::empty;
using record::labelPoint;
using record::outside;
using record::toUtf8;

namespace {

constexpr int kWidth = kPictureWidth, kArena = kArenaHeight, kHeight = kPictureHeight;

// ---- how things are drawn (pixels)
constexpr double kReferenceHalfWidth = 4.5;  ///< the solution's trail: a band 9 px wide
constexpr double kStudentHalfWidth = 1.0;    ///< the student's trail: a line 2 px wide
constexpr double kPathHalfWidth = 0.75;       ///< the robot's path: a pale line 1.5 px wide
constexpr double kRingHalfWidth = 1.25;      ///< a robot's end circle: 2.5 px
constexpr double kOutlineHalfWidth = 1.0;    ///< a region's outline: 2 px
constexpr double kWaypointRadius = 5;
constexpr int kHatchSpacing = 9;             ///< avoid regions: diagonal lines this far apart
constexpr uint32_t kWhite = 0xFFFFFF;
constexpr uint32_t kTextColour = 0x202020;
constexpr uint32_t kFrameColour = 0xB4B4B4;
constexpr uint32_t kLegendBackground = 0xF6F6F6;

/// A coordinate as a whole pixel, floor or ceiling, kept far from int's limits (and NaN, which
/// no assignment should give, becomes a pixel far outside the picture).
int floorPixel(double v) { return v > -1e6 ? (v < 1e6 ? static_cast<int>(std::floor(v)) : 1'000'000) : -1'000'000; }
int ceilPixel(double v) { return v > -1e6 ? (v < 1e6 ? static_cast<int>(std::ceil(v)) : 1'000'000) : -1'000'000; }

/// A pixel rectangle, inclusive at both ends.
struct Box {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x0 > x1 || y0 > y1; }
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
  bool overlaps(const Box& b) const { return x0 <= b.x1 && b.x0 <= x1 && y0 <= b.y1 && b.y0 <= y1; }
  bool inside(const Box& outer) const {
    return x0 >= outer.x0 && y0 >= outer.y0 && x1 <= outer.x1 && y1 <= outer.y1;
  }
  Box grown(int by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
  Box clipped(const Box& c) const {
    return {std::max(x0, c.x0), std::max(y0, c.y0), std::min(x1, c.x1), std::min(y1, c.y1)};
  }
};

constexpr Box kArenaBox{0, 0, kWidth - 1, kArena - 1};
constexpr Box kLegendBox{0, kArena, kWidth - 1, kHeight - 1};

/// How much of each pixel one layer of the picture covers (0..1), before it is painted in one
/// colour. A shape made of pieces (a trail's segments) is covered once, so its anti-aliased
/// edges do not darken where the pieces overlap. Nothing outside `clip` is ever covered: the
/// arena's drawing never spills into the legend. The amounts are kept in tiles of 32 x 32
/// pixels made when something first covers them: a layer is mostly empty (a trail, a ring), and
/// a picture has a dozen layers, which as whole arrays cost more in fresh pages than in drawing.
class Coverage {
 public:
  explicit Coverage(Box clip) : clip_(clip) {
    if (clip.empty()) return;
    tilesX_ = (clip.width() + kTile - 1) / kTile;
    tiles_.resize(static_cast<size_t>(tilesX_) * static_cast<size_t>((clip.height() + kTile - 1) / kTile));
  }

  const Box& clip() const { return clip_; }
  /// The pixels a shape may cover, given its bounds in picture coordinates.
  Box area(double x0, double y0, double x1, double y1) const {
    return Box{floorPixel(x0), floorPixel(y0), ceilPixel(x1), ceilPixel(y1)}.clipped(clip_);
  }
  void cover(int x, int y, double amount) {
    if (amount <= 0 || x < clip_.x0 || x > clip_.x1 || y < clip_.y0 || y > clip_.y1) return;
    std::unique_ptr<float[]>& tile = tiles_[tileOf(x, y)];
    if (!tile) tile = std::make_unique<float[]>(kTile * kTile);  // zeroed
    float& p = tile[cellOf(x, y)];
    p = std::max(p, static_cast<float>(std::min(amount, 1.0)));
    if (dirty_.empty()) {
      dirty_ = {x, y, x, y};
    } else {
      dirty_.x0 = std::min(dirty_.x0, x), dirty_.x1 = std::max(dirty_.x1, x);
      dirty_.y0 = std::min(dirty_.y0, y), dirty_.y1 = std::max(dirty_.y1, y);
    }
  }
  /// Every pixel within one pixel of a covered one (a halo around text).
  Coverage grown() const {
    Coverage g(clip_);
    visit(dirty_, [&](int x, int y, float a) {
      if (a > 0)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) g.cover(x + dx, y + dy, 1);
    });
    return g;
  }
  /// Paints the covered pixels in `colour`, `opacity` of the way over what is there.
  void paint(render::RgbImage& img, uint32_t colour, double opacity = 1) const {
    visit(dirty_, [&](int x, int y, float amount) {
      double a = amount * opacity;
      if (a <= 0) return;
      img.set(x, y, a >= 1 ? colour : mix(img.pixel(x, y), colour, a));
    });
  }
  /// How many covered pixels `box` holds (where a label would hide something).
  int count(const Box& box) const {
    int n = 0;
    visit(box.clipped(clip_), [&](int, int, float a) { n += a > 0.25 ? 1 : 0; });
    return n;
  }

  static uint32_t mix(uint32_t under, uint32_t over, double a) {
    auto channel = [&](int shift) {
      double u = (under >> shift) & 0xFF, o = (over >> shift) & 0xFF;
      return static_cast<uint32_t>(std::lround(u + (o - u) * a)) << shift;
    };
    return channel(16) | channel(8) | channel(0);
  }

 private:
  static constexpr int kTile = 32;
  size_t tileOf(int x, int y) const {
    return static_cast<size_t>((y - clip_.y0) / kTile) * static_cast<size_t>(tilesX_) +
           static_cast<size_t>((x - clip_.x0) / kTile);
  }
  size_t cellOf(int x, int y) const {
    return static_cast<size_t>((y - clip_.y0) % kTile) * kTile + static_cast<size_t>((x - clip_.x0) % kTile);
  }
  /// Calls f(x, y, amount) for every pixel of `b` (inside the clip) in a tile that was made.
  template <class F>
  void visit(const Box& b, F&& f) const {
    if (b.empty()) return;
    const int tx0 = (b.x0 - clip_.x0) / kTile, tx1 = (b.x1 - clip_.x0) / kTile;
    const int ty0 = (b.y0 - clip_.y0) / kTile, ty1 = (b.y1 - clip_.y0) / kTile;
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        const float* tile = tiles_[static_cast<size_t>(ty) * static_cast<size_t>(tilesX_) + static_cast<size_t>(tx)].get();
        if (!tile) continue;
        const int x0 = std::max(b.x0, clip_.x0 + tx * kTile), x1 = std::min(b.x1, clip_.x0 + tx * kTile + kTile - 1);
        const int y0 = std::max(b.y0, clip_.y0 + ty * kTile), y1 = std::min(b.y1, clip_.y0 + ty * kTile + kTile - 1);
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) f(x, y, tile[cellOf(x, y)]);
      }
  }
  Box clip_;
  Box dirty_;
  int tilesX_ = 0;
  std::vector<std::unique_ptr<float[]>> tiles_;
};

/// Coverage of a pixel whose centre is `d` from a line's middle, for a line `halfWidth` wide on
/// each side: full inside, fading over the last pixel.
double edge(double halfWidth, double d) { return std::clamp(halfWidth + 0.5 - d, 0.0, 1.0); }

void segment(Coverage& c, P2 a, P2 b, double halfWidth) {
  const double m = halfWidth + 1;
  Box box = c.area(std::min(a.x, b.x) - m, std::min(a.y, b.y) - m, std::max(a.x, b.x) + m, std::max(a.y, b.y) + m);
  const double dy = b.y - a.y;
  for (int y = box.y0; y <= box.y1; ++y) {
    // Only the columns near the part of the segment within m of this row (a long diagonal
    // segment's box is mostly empty).
    double t0 = 0, t1 = 1;
    if (std::abs(dy) > 1e-9) {
      t0 = std::clamp((y - m - a.y) / dy, 0.0, 1.0), t1 = std::clamp((y + m - a.y) / dy, 0.0, 1.0);
      if (t0 > t1) std::swap(t0, t1);
    }
    const double xa = a.x + (b.x - a.x) * t0, xb = a.x + (b.x - a.x) * t1;
    const int x0 = std::max(box.x0, floorPixel(std::min(xa, xb) - m)), x1 = std::min(box.x1, ceilPixel(std::max(xa, xb) + m));
    for (int x = x0; x <= x1; ++x) c.cover(x, y, edge(halfWidth, distanceToSegment({double(x), double(y)}, a, b)));
  }
}

/// The pieces of a path once each: a piece driven again (a program going round a square
/// 25,000 times) covers nothing new, since coverage keeps the most any piece gives a pixel.
class PieceSet {
 public:
  /// True the first time the piece from a to b is seen.
  bool first(P2 a, P2 b) {
    Piece p{};
    const double v[4] = {a.x, a.y, b.x, b.y};
    std::memcpy(p.bits, v, sizeof v);
    return seen_.insert(p).second;
  }

 private:
  struct Piece {
    uint64_t bits[4];
    friend bool operator==(const Piece&, const Piece&) = default;
  };
  struct Hash {
    size_t operator()(const Piece& p) const {
      uint64_t h = 0;
      for (uint64_t v : p.bits) h = (h ^ v) * 0x9E3779B97F4A7C15ull, h ^= h >> 29;
      return static_cast<size_t>(h);
    }
  };
  std::unordered_set<Piece, Hash> seen_;
};

void polylines(Coverage& c, const Polylines& lines, double halfWidth) {
  PieceSet drawn;
  for (const Polyline& l : lines) {
    if (l.size() == 1 && drawn.first(l[0], l[0])) segment(c, l[0], l[0], halfWidth);
    for (size_t i = 1; i < l.size(); ++i)
      if (drawn.first(l[i - 1], l[i])) segment(c, l[i - 1], l[i], halfWidth);
  }
}

void ring(Coverage& c, P2 centre, double r, double halfWidth) {
  const double m = r + halfWidth + 1;
  Box box = c.area(centre.x - m, centre.y - m, centre.x + m, centre.y + m);
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x)
      c.cover(x, y, edge(halfWidth, std::abs(std::hypot(x - centre.x, y - centre.y) - r)));
}

/// An X of two strokes, `r` from its centre to each end.
void cross(Coverage& c, P2 centre, double r) {
  segment(c, {centre.x - r, centre.y - r}, {centre.x + r, centre.y + r}, 1.6);
  segment(c, {centre.x - r, centre.y + r}, {centre.x + r, centre.y - r}, 1.6);
}

void disc(Coverage& c, P2 centre, double r) {
  Box box = c.area(centre.x - r - 1, centre.y - r - 1, centre.x + r + 1, centre.y + r + 1);
  for (int y = box.y0; y <= box.y1; ++y)
    for (int x = box.x0; x <= box.x1; ++x) c.cover(x, y, edge(r, std::hypot(x - centre.x, y - centre.y)));
}

void box(Coverage& c, const Box& b) {
  Box k = b.clipped(c.clip());
  for (int y = k.y0; y <= k.y1; ++y)
    for (int x = k.x0; x <= k.x1; ++x) c.cover(x, y, 1);
}

/// The corners of a region's outline (a circle has none: see outlineRegion).
std::vector<P2> corners(const Region& r) {
  if (r.kind == Region::Rect) return {{r.x1, r.y1}, {r.x2, r.y1}, {r.x2, r.y2}, {r.x1, r.y2}};
  return r.points;
}

struct Bounds {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
Bounds bounds(const Region& r) {
  if (r.kind == Region::Circle) return {r.cx - r.r, r.cy - r.r, r.cx + r.r, r.cy + r.r};
  Bounds b{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
           std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (const P2& p : corners(r))
    b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
  if (b.x0 > b.x1) return {};
  return b;
}

void outlineRegion(Coverage& c, const Region& r, double halfWidth) {
  if (r.kind == Region::Circle) {
    ring(c, {r.cx, r.cy}, r.r, halfWidth);
    return;
  }
  std::vector<P2> pts = corners(r);
  for (size_t i = 0; i < pts.size(); ++i) segment(c, pts[i], pts[(i + 1) % pts.size()], halfWidth);
}

/// The inside of a region; `hatch` keeps only diagonal lines across it.
void fillRegion(Coverage& c, const Region& r, bool hatch) {
  Bounds b = bounds(r);
  Box area = c.area(b.x0, b.y0, b.x1, b.y1);
  for (int y = area.y0; y <= area.y1; ++y)
    for (int x = area.x0; x <= area.x1; ++x) {
      if (hatch && (x + y) % kHatchSpacing != 0) continue;
      if (outside(r, {double(x), double(y)}) == 0) c.cover(x, y, 1);
    }
}

/// The pixels of `clip` a region (with its outline) may cover.
Box near(const Region& r, const Box& clip) {
  Bounds b = bounds(r);
  return Box{floorPixel(b.x0) - 3, floorPixel(b.y0) - 3, ceilPixel(b.x1) + 3, ceilPixel(b.y1) + 3}.clipped(clip);
}
/// The pixels of `clip` a circle of radius r around `c` (with its outline) may cover.
Box near(P2 c, double r, const Box& clip) {
  Region g;
  g.kind = Region::Circle, g.cx = c.x, g.cy = c.y, g.r = r;
  return near(g, clip);
}

uint32_t fade(uint32_t rgb) {
  auto lighten = [](uint32_t c) { return 255 - (255 - c) / 4; };
  uint32_t r = lighten(rgb >> 16 & 0xFF), g = lighten(rgb >> 8 & 0xFF), b = lighten(rgb & 0xFF);
  return r << 16 | g << 8 | b;
}

/// A darker shade of a colour, for text that must read well on white.
uint32_t darker(uint32_t rgb) { return Coverage::mix(rgb, 0x000000, 0.3); }

/// The screen faded into the arena (only a whole 800 x 600 screen).
void fadedScreen(render::RgbImage& img, const std::shared_ptr<const render::RgbImage>& screen) {
  if (!screen || screen->width != kWidth || screen->height != kArena ||
      screen->rgb.size() != static_cast<size_t>(kWidth) * kArena * 3)
    return;
  // fade() a byte at a time: the arena is the picture's first rows, as wide as the screen.
  uint8_t lighter[256];
  for (uint32_t c = 0; c < 256; ++c) lighter[c] = static_cast<uint8_t>(fade(c) & 0xFF);
  const size_t bytes = static_cast<size_t>(kWidth) * kArena * 3;
  const uint8_t* from = screen->rgb.data();
  uint8_t* to = img.rgb.data();
  for (size_t i = 0; i < bytes; ++i) to[i] = lighter[from[i]];
}

/// The fonts draw Latin-1: UTF-8 text (assignment files) is decoded, a character beyond
/// Latin-1 becomes '?', and a byte that is not UTF-8 stays (already Latin-1, as toUtf8 reads it).
std::string latin1(std::string_view s) {
  const std::string valid = toUtf8(s);
  std::string out;
  for (size_t i = 0; i < valid.size();) {
    const auto b = static_cast<unsigned char>(valid[i]);
    const size_t n = b < 0x80 ? 1 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : 4;  // well-formed: a lead byte
    if (n == 1) out += static_cast<char>(b);
    else if (n == 2 && b <= 0xC3) out += static_cast<char>((b & 0x1F) << 6 | (static_cast<unsigned char>(valid[i + 1]) & 0x3F));
    else out += '?';
    i += n;
  }
  return out;
}

/// Latin-1 text back as UTF-8 (what legendEntries returns).
std::string utf8(std::string_view latin) {
  std::string out;
  for (char ch : latin) {
    auto b = static_cast<unsigned char>(ch);
    if (b < 0x80) {
      out += ch;
    } else {
      out += static_cast<char>(0xC0 | b >> 6);
      out += static_cast<char>(0x80 | (b & 0x3F));
    }
  }
  return out;
}

// ---- text

const FontKey kLabelFont{Typeface::Sans, false, false, 13};
const FontKey kNumberFont{Typeface::Sans, true, false, 13};
const FontKey kLegendFont{Typeface::Sans, false, false, 13};

/// Text in the embedded fonts (monochrome, as the screen draws it).
class Writer {
 public:
  int width(const FontKey& k, std::string_view s) { return fonts_.width(k, s); }
  int height(const FontKey& k) { return fonts_.metrics(k).lineHeight; }
  /// The box the text takes with its top-left corner at (x, top).
  Box extent(const FontKey& k, int x, int top, std::string_view s) {
    return {x, top, x + std::max(width(k, s), 1) - 1, top + height(k) - 1};
  }
  /// `s` shortened with "..." to at most `maxWidth` pixels.
  std::string fit(const FontKey& k, std::string s, int maxWidth) {
    if (width(k, s) <= maxWidth) return s;
    s.resize(std::min(s.size(), static_cast<size_t>(std::max(maxWidth, 0))));  // a glyph is 1 px or wider
    while (!s.empty() && width(k, s + "...") > maxWidth) s.pop_back();
    return s + "...";
  }
  void draw(Coverage& c, const FontKey& k, int x, int top, std::string_view s) {
    const int baseline = top + fonts_.metrics(k).ascent;
    fonts_.glyphs(k, s, glyphs_, s.size());
    int pen = x;
    for (const Glyph* g : glyphs_) {
      const int left = pen + g->left, gtop = baseline - g->top;
      for (const Glyph::Run& r : g->runs)
        for (int i = 0; i < r.length; ++i) c.cover(left + r.x + i, gtop + r.y, 1);
      pen += g->advance;
    }
  }
  /// Text in `colour` with a white halo, so it reads over trails and drawings.
  void write(render::RgbImage& img, const Box& clip, const FontKey& k, int x, int top,
             std::string_view s, uint32_t colour, bool halo) {
    Coverage c(extent(k, x, top, s).grown(4).clipped(clip));  // glyphs may overhang a little
    draw(c, k, x, top, s);
    if (halo) c.grown().paint(img, kWhite, 0.85);
    c.paint(img, colour);
  }

 private:
  FontRenderer fonts_;
  std::vector<const Glyph*> glyphs_;
};

/// A white box with a thin frame (`opacity`: how much it hides): the ground of a label.
void labelBox(render::RgbImage& img, const Box& b, uint32_t frame, double opacity) {
  Coverage fill(b.clipped(kArenaBox)), edgeLine(b.clipped(kArenaBox));
  box(fill, b);
  fill.paint(img, kWhite, opacity);
  box(edgeLine, {b.x0, b.y0, b.x1, b.y0});
  box(edgeLine, {b.x0, b.y1, b.x1, b.y1});
  box(edgeLine, {b.x0, b.y0, b.x0, b.y1});
  box(edgeLine, {b.x1, b.y0, b.x1, b.y1});
  edgeLine.paint(img, frame);
}

/// Where labels go in the arena: of the candidate places, the one that overlaps no label placed
/// before, stays in the arena and hides the least of the trails.
class Labels {
 public:
  explicit Labels(std::vector<const Coverage*> avoid) : avoid_(std::move(avoid)) {}
  void reserve(const Box& b) { placed_.push_back(b); }
  /// The chosen box among `candidates` (in order of preference), reserved.
  Box place(const std::vector<Box>& candidates) {
    Box best = candidates.front();
    long bestScore = std::numeric_limits<long>::max();
    for (size_t i = 0; i < candidates.size(); ++i) {
      const Box& b = candidates[i];
      long score = static_cast<long>(i);  // earlier candidates win ties
      if (!b.inside(kArenaBox)) score += 1'000'000;
      for (const Box& p : placed_)
        if (b.overlaps(p)) score += 100'000;
      for (const Coverage* c : avoid_) score += 20L * c->count(b);
      if (score < bestScore) bestScore = score, best = b;
    }
    // Keep it in the arena even when nothing fits.
    int dx = best.x0 < 0 ? -best.x0 : best.x1 >= kWidth ? kWidth - 1 - best.x1 : 0;
    int dy = best.y0 < 0 ? -best.y0 : best.y1 >= kArena ? kArena - 1 - best.y1 : 0;
    best = {best.x0 + dx, best.y0 + dy, best.x1 + dx, best.y1 + dy};
    placed_.push_back(best);
    return best;
  }

 private:
  std::vector<const Coverage*> avoid_;
  std::vector<Box> placed_;
};

/// How many pixels of `b` (within the arena) are not white.
int ink(const render::RgbImage& img, const Box& b) {
  Box k = b.clipped(kArenaBox);
  int n = 0;
  for (int y = k.y0; y <= k.y1; ++y)
    for (int x = k.x0; x <= k.x1; ++x) n += img.pixel(x, y) != kWhite ? 1 : 0;
  return n;
}

/// A box of w x h pixels centred on (x, y).
Box centred(double x, double y, int w, int h) {
  int x0 = floorPixel(x - w / 2.0 + 0.5), y0 = floorPixel(y - h / 2.0 + 0.5);
  return {x0, y0, x0 + w - 1, y0 + h - 1};
}

// ---- the legend

/// One entry of the legend; its text in Latin-1, as the fonts draw it.
struct LegendItem {
  enum Swatch { StudentTrail, StudentPath, StudentEnd, Failure, ReferenceTrail, ReferenceEnd, Waypoint, Goal, Avoid,
                Colour } swatch;
  std::string text;
  Region::Kind shape = Region::Rect;  ///< a region's swatch: a small square or circle
  uint32_t rgb = 0;                   ///< a colour's swatch
};

bool drawsReference(const PictureInput& in) { return !in.studentView && !empty(in.reference); }
bool drawsReferenceEnd(const PictureInput& in) { return !in.studentView && in.referenceEnd.has_value(); }

constexpr int kSwatchWidth = 30, kSwatchGap = 7, kItemGap = 24, kMaxItemGap = 40, kLegendMargin = 14;
constexpr int kRowHeight = 24, kLegendRows = 2, kMaxLabelWidth = 260;

/// The student's things, the solution's, then what the assignment asked for.
int group(const LegendItem& it) {
  switch (it.swatch) {
    case LegendItem::StudentTrail:
    case LegendItem::StudentPath:
    case LegendItem::StudentEnd:
    case LegendItem::Failure: return 0;
    case LegendItem::ReferenceTrail:
    case LegendItem::ReferenceEnd: return 1;
    default: return 2;
  }
}

/// Where each legend item goes: x0..x1 its swatch and text, y0 its row (0 or 1; drawLegend
/// places the rows). In order of preference: all on one row; a grid whose columns hold two
/// items each, a column never mixing the student's, the solution's and the assignment's
/// things; two rows filled left to right. False when none fits the strip.
bool layOut(Writer& w, const std::vector<LegendItem>& items, std::vector<Box>& boxes) {
  const int right = kWidth - kLegendMargin;
  std::vector<int> widths;
  for (const LegendItem& it : items) widths.push_back(kSwatchWidth + kSwatchGap + w.width(kLegendFont, it.text));
  // Left to right, wrapping at the right edge (one row when it all fits).
  auto flow = [&] {
    boxes.clear();
    int x = kLegendMargin, row = 0;
    for (int width : widths) {
      if (x > kLegendMargin && x + width > right) x = kLegendMargin, ++row;
      boxes.push_back({x, row, x + width - 1, row});
      x += width + kItemGap;
    }
    return row < kLegendRows;
  };
  if (flow() && (boxes.empty() || boxes.back().y0 == 0)) return true;
  // The grid: columns of kLegendRows items, spread over the width (up to kMaxItemGap apart).
  std::vector<std::vector<size_t>> columns;
  for (size_t i = 0; i < items.size(); ++i) {
    if (columns.empty() || columns.back().size() == kLegendRows || group(items[i]) != group(items[columns.back()[0]]))
      columns.emplace_back();
    columns.back().push_back(i);
  }
  std::vector<int> columnWidths;
  int total = 0;
  for (const std::vector<size_t>& c : columns) {
    int cw = 0;
    for (size_t i : c) cw = std::max(cw, widths[i]);
    columnWidths.push_back(cw);
    total += cw;
  }
  const int gaps = static_cast<int>(columns.size()) - 1;
  const int room = right - kLegendMargin - total;
  if (gaps > 0 && room >= gaps * kItemGap) {
    const int gap = std::min(kMaxItemGap, room / gaps);
    boxes.assign(items.size(), Box{});
    int x = kLegendMargin;
    for (size_t c = 0; c < columns.size(); ++c) {
      for (size_t r = 0; r < columns[c].size(); ++r) {
        const int row = static_cast<int>(r);
        boxes[columns[c][r]] = {x, row, x + widths[columns[c][r]] - 1, row};
      }
      x += columnWidths[c] + gap;
    }
    return true;
  }
  return flow();
}

/// What the legend lists: one item for each kind of thing the picture draws. When the items
/// do not fit the strip, regions are named by their role only ("goal regions"), their labels
/// being written in the arena anyway.
std::vector<LegendItem> legendItems(const PictureInput& in, Writer& w) {
  std::vector<LegendItem> items;
  if (!empty(in.student)) items.push_back({LegendItem::StudentTrail, "your trail"});
  if (!empty(in.studentPath)) items.push_back({LegendItem::StudentPath, "your robot's path"});
  if (in.studentEnd) items.push_back({LegendItem::StudentEnd, "where your robot ended"});
  if (!in.failures.empty())
    items.push_back({LegendItem::Failure, in.failures.size() == 1 ? "where a check failed" : "where checks failed"});
  if (drawsReference(in)) items.push_back({LegendItem::ReferenceTrail, "the solution's trail"});
  if (drawsReferenceEnd(in)) items.push_back({LegendItem::ReferenceEnd, "where the solution's robot ended"});
  if (!in.waypoints.empty())
    items.push_back({LegendItem::Waypoint, in.waypoints.size() == 1 ? "waypoint" : "waypoints, in order"});
  // One item per labelled region (the same label and role once), or per role only.
  auto regionItems = [&](bool named) {
    std::vector<LegendItem> out;
    std::vector<int> count;  // how many regions each item stands for
    for (const PictureRegion& r : in.regions) {
      const bool goal = r.role == PictureRegion::Goal;
      const std::string label = named ? w.fit(kLegendFont, latin1(r.label), kMaxLabelWidth) : "";
      LegendItem it{goal ? LegendItem::Goal : LegendItem::Avoid, label,
                    r.region.kind == Region::Circle ? Region::Circle : Region::Rect};
      auto same = std::find_if(out.begin(), out.end(), [&](const LegendItem& o) {
        return o.swatch == it.swatch && o.text == it.text;
      });
      if (same == out.end()) {
        out.push_back(it);
        count.push_back(1);
      } else {
        ++count[static_cast<size_t>(same - out.begin())];
        if (same->shape != it.shape) same->shape = Region::Rect;  // mixed shapes: a square
      }
    }
    for (size_t i = 0; i < out.size(); ++i) {
      const bool goal = out[i].swatch == LegendItem::Goal, many = count[i] > 1;
      if (!out[i].text.empty())
        out[i].text.insert(0, goal ? "reach: " : "keep out: ");
      else if (goal)
        out[i].text = many ? "goal regions" : "goal region";
      else
        out[i].text = many ? "areas to avoid" : "area to avoid";
    }
    return out;
  };
  // The colours colour checks watch, named (or by role only when there is no room).
  auto colourItems = [&](bool named) {
    std::vector<LegendItem> out;
    for (const PictureColour& c : in.colours) {
      std::string text = (c.avoid ? "keep off: " : "touch: ") +
                         (named ? w.fit(kLegendFont, latin1(c.label), kMaxLabelWidth) : std::string("a colour"));
      LegendItem it{LegendItem::Colour, text, Region::Rect, c.rgb};
      if (std::none_of(out.begin(), out.end(), [&](const LegendItem& o) { return o.text == it.text && o.rgb == it.rgb; }))
        out.push_back(it);
    }
    return out;
  };
  std::vector<LegendItem> all = items;
  for (LegendItem& it : regionItems(true)) all.push_back(std::move(it));
  for (LegendItem& it : colourItems(true)) all.push_back(std::move(it));
  std::vector<Box> boxes;
  if (layOut(w, all, boxes)) return all;
  for (LegendItem& it : regionItems(false)) items.push_back(std::move(it));
  for (LegendItem& it : colourItems(false)) items.push_back(std::move(it));
  return items;
}

void drawSwatch(render::RgbImage& img, const LegendItem& it, int x, int mid) {
  Coverage c(kLegendBox);
  const double cx = x + kSwatchWidth / 2.0, y = mid;
  switch (it.swatch) {
    case LegendItem::StudentTrail:
      segment(c, {x + 3.0, y}, {x + kSwatchWidth - 4.0, y}, kStudentHalfWidth);
      c.paint(img, kStudentColour);
      return;
    case LegendItem::ReferenceTrail:
      segment(c, {x + 5.0, y}, {x + kSwatchWidth - 6.0, y}, kReferenceHalfWidth);
      c.paint(img, kReferenceColour);
      return;
    case LegendItem::StudentPath:
      segment(c, {x + 3.0, y}, {x + kSwatchWidth - 4.0, y}, kPathHalfWidth);
      c.paint(img, kPathColour);
      return;
    case LegendItem::Failure:
      cross(c, {cx, y}, 6);
      c.paint(img, kFailColour);
      return;
    case LegendItem::Colour: {
      for (int yy = mid - 7; yy <= mid + 7; ++yy)
        for (int xx = x + 7; xx <= x + kSwatchWidth - 8; ++xx) {
          bool rim = yy == mid - 7 || yy == mid + 7 || xx == x + 7 || xx == x + kSwatchWidth - 8;
          img.set(xx, yy, rim ? kTextColour : it.rgb);
        }
      return;
    }
    case LegendItem::StudentEnd:
    case LegendItem::ReferenceEnd:
      ring(c, {cx, y}, 7, kRingHalfWidth);
      c.paint(img, it.swatch == LegendItem::StudentEnd ? kStudentColour : kReferenceColour);
      return;
    case LegendItem::Waypoint:
      disc(c, {cx, y}, kWaypointRadius);
      c.paint(img, kWaypointColour);
      return;
    case LegendItem::Goal:
    case LegendItem::Avoid: {
      Region r;
      r.kind = it.shape;
      r.x1 = x + 6, r.x2 = x + kSwatchWidth - 7, r.y1 = mid - 7, r.y2 = mid + 7;
      r.cx = cx, r.cy = mid, r.r = 8;
      bool avoid = it.swatch == LegendItem::Avoid;
      uint32_t colour = avoid ? kAvoidColour : kGoalColour;
      Coverage tint(kLegendBox), hatch(kLegendBox);
      fillRegion(tint, r, false);
      tint.paint(img, colour, avoid ? 0.14 : 0.08);
      if (avoid) {
        fillRegion(hatch, r, true);
        hatch.paint(img, colour, 0.55);
      }
      outlineRegion(c, r, kOutlineHalfWidth);
      c.paint(img, colour);
      return;
    }
  }
}

void drawLegend(render::RgbImage& img, const std::vector<LegendItem>& items, Writer& w) {
  for (int y = kArena; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) img.set(x, y, y == kArena ? kFrameColour : kLegendBackground);
  std::vector<Box> boxes;
  layOut(w, items, boxes);
  int rows = 0;
  for (const Box& b : boxes) rows = std::max(rows, b.y0 + 1);
  const int top = kArena + 1 + (kHeight - kArena - 1 - rows * kRowHeight) / 2;
  for (size_t i = 0; i < items.size(); ++i) {
    const int rowTop = top + boxes[i].y0 * kRowHeight, mid = rowTop + kRowHeight / 2;
    if (rowTop + kRowHeight > kHeight) continue;  // no room (cannot happen with role-only regions)
    drawSwatch(img, items[i], boxes[i].x0, mid);
    const int textTop = mid - w.height(kLegendFont) / 2;
    w.write(img, kLegendBox, kLegendFont, boxes[i].x0 + kSwatchWidth + kSwatchGap, textTop, items[i].text,
            kTextColour, false);
  }
}

}  // namespace

struct PicturePainter::Impl {
  Writer writer;
};

PicturePainter::PicturePainter() : impl_(std::make_unique<Impl>()) {}
PicturePainter::~PicturePainter() = default;

std::vector<std::string> legendEntries(const PictureInput& in) { return PicturePainter().legend(in); }
render::RgbImage feedbackPicture(const PictureInput& in) { return PicturePainter().picture(in); }

std::vector<std::string> PicturePainter::legend(const PictureInput& in) {
  std::vector<std::string> out;
  for (const LegendItem& it : legendItems(in, impl_->writer)) out.push_back(utf8(it.text));
  return out;
}

render::RgbImage PicturePainter::picture(const PictureInput& in) {
  render::RgbImage img;
  img.width = kWidth;
  img.height = kHeight;
  img.rgb.assign(static_cast<size_t>(kWidth) * kHeight * 3, 0xFF);
  Writer& w = impl_->writer;

  // The ground: the solution's final screen for the teacher, the student's own for them.
  fadedScreen(img, in.studentView ? in.studentScreen : in.background);

  // What labels should not hide: the trails, and the marks (end circles, region outlines).
  Coverage reference(kArenaBox), student(kArenaBox), marks(kArenaBox);
  if (drawsReference(in)) {
    polylines(reference, in.reference, kReferenceHalfWidth);
    reference.paint(img, kReferenceColour);
  }
  if (drawsReferenceEnd(in)) {
    Coverage end(near(*in.referenceEnd, in.robotRadius, kArenaBox));
    ring(end, *in.referenceEnd, in.robotRadius, kRingHalfWidth);
    end.paint(img, kReferenceColour);
    ring(marks, *in.referenceEnd, in.robotRadius, kRingHalfWidth);
  }

  for (const PictureRegion& r : in.regions) {
    const bool avoid = r.role == PictureRegion::Avoid;
    const uint32_t colour = avoid ? kAvoidColour : kGoalColour;
    const Box area = near(r.region, kArenaBox);
    Coverage tint(area), outline(area);
    fillRegion(tint, r.region, false);
    tint.paint(img, colour, avoid ? 0.10 : 0.06);
    if (avoid) {
      Coverage hatch(area);
      fillRegion(hatch, r.region, true);
      hatch.paint(img, colour, 0.45);
    }
    outlineRegion(outline, r.region, kOutlineHalfWidth);
    outline.paint(img, colour);
    outlineRegion(marks, r.region, kOutlineHalfWidth);
  }

  if (!in.waypoints.empty()) {
    Coverage dots(kArenaBox), rims(kArenaBox);
    for (const P2& p : in.waypoints) {
      disc(dots, p, kWaypointRadius);
      ring(rims, p, kWaypointRadius + 1, 0.6);
    }
    rims.paint(img, kWhite);
    dots.paint(img, kWaypointColour);
  }

  // The path under the trail: where the robot went, also with its pen up.
  Coverage path(kArenaBox);
  polylines(path, in.studentPath, kPathHalfWidth);
  path.paint(img, kPathColour);
  polylines(student, in.student, kStudentHalfWidth);
  student.paint(img, kStudentColour);
  Coverage crosses(kArenaBox);
  for (const PictureMark& m : in.failures) cross(crosses, m.at, 7);
  crosses.grown().paint(img, kWhite);
  crosses.paint(img, kFailColour);
  for (const PictureMark& m : in.failures) cross(marks, m.at, 7);
  if (in.studentEnd) {
    Coverage end(near(*in.studentEnd, in.robotRadius, kArenaBox));
    ring(end, *in.studentEnd, in.robotRadius, kRingHalfWidth);
    end.paint(img, kStudentColour);
    ring(marks, *in.studentEnd, in.robotRadius, kRingHalfWidth);
  }

  // Words last, placed where they hide the least of the trails.
  Labels labels({&student, &reference, &marks});
  if (!in.title.empty()) {
    // At the top left, unless it would hide something there that another corner would not
    // (a program's printed output starts at the top left).
    const std::string title = w.fit(kLabelFont, latin1(in.title), 480);
    const int tw = w.width(kLabelFont, title), th = w.height(kLabelFont), m = 10;
    Box best;
    int fewest = std::numeric_limits<int>::max();
    for (Box b : {Box{m, m, m + tw - 1, m + th - 1}, Box{kWidth - m - tw, m, kWidth - m - 1, m + th - 1},
                  Box{m, kArena - m - th, m + tw - 1, kArena - m - 1},
                  Box{kWidth - m - tw, kArena - m - th, kWidth - m - 1, kArena - m - 1}}) {
      const int n = ink(img, b.grown(6));
      if (n < fewest) fewest = n, best = b;
    }
    labelBox(img, best.grown(4), kFrameColour, 1);
    w.write(img, kArenaBox, kLabelFont, best.x0, best.y0, title, kTextColour, false);
    labels.reserve(best.grown(6));
  }
  for (const P2& p : in.waypoints) labels.reserve(centred(p.x, p.y, 12, 12));
  for (const PictureRegion& r : in.regions) {
    const std::string text = w.fit(kLabelFont, latin1(r.label), 300);
    if (text.empty()) continue;
    const uint32_t colour = darker(r.role == PictureRegion::Avoid ? kAvoidColour : kGoalColour);
    const int tw = w.width(kLabelFont, text) + 8, th = w.height(kLabelFont) + 4;
    const P2 at = labelPoint(r.region);
    const Bounds b = bounds(r.region);
    std::vector<Box> candidates;
    // Inside when it fits there; else just below, above, right or left of the region.
    if (tw + 6 <= b.x1 - b.x0 && th + 6 <= b.y1 - b.y0) {
      candidates.push_back(centred(at.x, at.y, tw, th));
      candidates.push_back(centred(at.x, at.y + th + 2, tw, th));
      candidates.push_back(centred(at.x, at.y - th - 2, tw, th));
    }
    candidates.push_back(centred(at.x, b.y1 + 4 + th / 2.0, tw, th));
    candidates.push_back(centred(at.x, b.y0 - 4 - th / 2.0, tw, th));
    candidates.push_back(centred(b.x1 + 4 + tw / 2.0, at.y, tw, th));
    candidates.push_back(centred(b.x0 - 4 - tw / 2.0, at.y, tw, th));
    const Box place = labels.place(candidates);
    labelBox(img, place, colour, 0.88);
    w.write(img, kArenaBox, kLabelFont, place.x0 + 4, place.y0 + 2, text, colour, false);
  }
  // Each failed check's name beside its cross.
  for (const PictureMark& m : in.failures) {
    const std::string text = w.fit(kLabelFont, latin1(m.label), 260);
    if (text.empty()) continue;
    const int tw = w.width(kLabelFont, text) + 8, th = w.height(kLabelFont) + 4;
    std::vector<Box> candidates;
    for (double off : {12.0, 24.0, in.robotRadius + 6})
      for (int sx : {1, -1})
        for (int sy : {-1, 1})
          candidates.push_back(centred(m.at.x + sx * (off + tw / 2.0), m.at.y + sy * (off / 2 + th / 2.0), tw, th));
    const Box place = labels.place(candidates);
    labelBox(img, place, kFailColour, 0.9);
    w.write(img, kArenaBox, kLabelFont, place.x0 + 4, place.y0 + 2, text, kFailColour, false);
  }
  // Waypoint numbers beside their markers; waypoints at the same place share one ("1, 5").
  std::vector<bool> done(in.waypoints.size(), false);
  for (size_t i = 0; i < in.waypoints.size(); ++i) {
    if (done[i]) continue;
    std::string text = std::to_string(i + 1);
    for (size_t j = i + 1; j < in.waypoints.size(); ++j)
      if (!done[j] && distance(in.waypoints[i], in.waypoints[j]) < 2 * kWaypointRadius) {
        text += ", " + std::to_string(j + 1);
        done[j] = true;
      }
    const P2 p = in.waypoints[i];
    const int tw = w.width(kNumberFont, text) + 2, th = w.height(kNumberFont);
    // Beside the marker, corners first; farther out when that would hide a line (the
    // robot's circle around a waypoint it ended on).
    std::vector<Box> candidates;
    for (double off : {kWaypointRadius + 3, kWaypointRadius + 12, in.robotRadius + 4}) {
      candidates.push_back(centred(p.x + off + tw / 2.0, p.y - off - th / 2.0 + 4, tw, th));
      candidates.push_back(centred(p.x - off - tw / 2.0, p.y - off - th / 2.0 + 4, tw, th));
      candidates.push_back(centred(p.x + off + tw / 2.0, p.y + off + th / 2.0 - 4, tw, th));
      candidates.push_back(centred(p.x - off - tw / 2.0, p.y + off + th / 2.0 - 4, tw, th));
      candidates.push_back(centred(p.x, p.y - off - th / 2.0, tw, th));
      candidates.push_back(centred(p.x, p.y + off + th / 2.0, tw, th));
    }
    const Box place = labels.place(candidates);
    w.write(img, kArenaBox, kNumberFont, place.x0 + 1, place.y0, text, kWaypointColour, true);
  }

  drawLegend(img, legendItems(in, w), w);
  return img;
}

}  // namespace rb::grade
