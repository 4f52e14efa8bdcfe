#pragma once
// The 800 x 600 screen. Every pixel keeps the colour number it was drawn with (0..15 for the
// palette, larger numbers for RGB() colours), so `rLook() = RED` compares exactly. Drawing is
// exact and deterministic (no anti-aliasing): the robot's sensors read these pixels.
//
// Besides the pixels the canvas keeps a display list of what was drawn, so that the SVG writer
// can emit real vector elements, and it tracks which pixels are obstacles for the robot
// (neither the background colour nor an invisible colour) so that the simulator knows when its
// obstacle map must be rebuilt.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "screen/font.h"
#include "base/large_memory.h"

namespace rb {

/// A colour number: 0..15 the palette, otherwise r + 256*g + 65536*b as RGB() makes it.
using Colour = uint32_t;
/// A whole screen of colours, row by row (see base/large_memory.h for where its memory comes from).
using Pixels = std::vector<Colour, LargeAllocator<Colour>>;

namespace colours {
constexpr Colour kBlack = 0, kBlue = 1, kGreen = 2, kCyan = 3, kRed = 4, kMagenta = 5,
                 kBrown = 6, kGray = 7, kDarkGray = 8, kLightBlue = 9, kLightGreen = 10,
                 kLightCyan = 11, kLightRed = 12, kLightMagenta = 13, kYellow = 14, kWhite = 15;
}  // namespace colours

/// 0xRRGGBB for a colour number (the 16 palette colours are RobotBASIC 4.2's; docs/graphics.md).
uint32_t colourToRgb(Colour c);
/// The colour number RGB(r, g, b) gives.
Colour rgbColour(int r, int g, int b);

struct Point {
  int x = 0, y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

/// A box of pixels, inclusive at both ends; empty until a pixel is added.
struct PixelBox {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -(1 << 30), y1 = -(1 << 30);
  bool empty() const { return x0 > x1; }
  void add(int x, int y) {
    x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
    y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
  }
  void add(const PixelBox& b) {
    if (b.empty()) return;
    add(b.x0, b.y0);
    add(b.x1, b.y1);
  }
  long area() const { return empty() ? 0 : long(x1 - x0 + 1) * long(y1 - y0 + 1); }
};

/// Where pixels changed since the last time the changes were taken: where obstacles changed
/// (Canvas::takeObstacleChanges), for the obstacle index of the simulator, which updates only
/// those regions, lazily; where any pixel changed (Canvas::takeChanges), for a grader's colour
/// watch. Changes far apart (a status line in a corner, the pen trail under the robot) stay in
/// separate boxes.
struct ChangeBoxes {
  static constexpr size_t kMaxBoxes = 8;
  /// Pixels this close to a box join it rather than start another.
  static constexpr int kJoin = 16;
  std::vector<PixelBox> boxes;  ///< every pixel that changed (became or stopped being an obstacle)
  bool all = false;             ///< something changed everywhere (clearScr, scrolling; rInvisible for obstacles)

  void add(int x, int y) { boxFor(x, y).add(x, y); }
  /// Pixels x1..x2 of row y: one box takes them all.
  void addRow(int y, int x1, int x2) {
    PixelBox& b = boxFor(x1, y);
    b.add(x1, y);
    b.add(x2, y);
  }

 private:
  /// The box a change at (x, y) joins (a new one if none is near).
  PixelBox& boxFor(int x, int y) {
    if (!boxes.empty()) {
      PixelBox& last = boxes.back();  // drawing is mostly local: the last box first
      if (x >= last.x0 - kJoin && x <= last.x1 + kJoin && y >= last.y0 - kJoin && y <= last.y1 + kJoin)
        return last;
    }
    return boxForFar(x, y);
  }
  PixelBox& boxForFar(int x, int y);
};

/// xyText's style bits, the constants fs_Bold, fs_Italic, fs_Underline, fs_StrikeOut (the
/// names are confirmed by a published program, the values are rb's choice).
constexpr int kFsBold = 1, kFsItalic = 2, kFsUnderline = 4, kFsStrikeOut = 8;

/// Text options of xyText. The default is the font of print and xyString: Mono (Courier New's
/// twin) at 10 points, 8 x 15 pixels a character.
struct TextStyle {
  FontKey font;               ///< face, bold, italic, size in pixels
  bool underline = false, strikeout = false;
  std::optional<Colour> background;  ///< opaque background behind the characters' cells
};

/// One entry of the display list.
struct DrawOp {
  enum Kind {
    Clear,     ///< colour: the whole screen
    Line,      ///< points[0..1], width, colour
    Rect,      ///< points[0] top-left, points[1] bottom-right (inclusive), width, colour, fill
    Ellipse,   ///< bounding box like Rect
    Polygon,   ///< points, width, colour, fill
    Pixel,     ///< points[0], colour
    Text,      ///< points[0] top-left, points[1] bottom-right (exclusive) of its cells, text,
               ///< style, colour, ascent (from the top to the baseline)
    Trail,     ///< a polyline the robot's pen drew: points, width, colour
    Raster,    ///< something with no vector form happened (flood fill, scrolling, restoreScr)
  };
  explicit DrawOp(Kind k, std::vector<Point> pts = {}, Colour c = 0,
                  std::optional<Colour> f = std::nullopt, int w = 1, std::string t = {},
                  TextStyle s = {})
      : kind(k), points(std::move(pts)), colour(c), fill(f), width(w), text(std::move(t)),
        style(s) {}

  Kind kind;
  std::vector<Point> points;
  Colour colour = 0;
  std::optional<Colour> fill;
  int width = 1;
  std::string text;
  TextStyle style;
  int ascent = 0;
};

class Canvas {
 public:
  static constexpr int kWidth = 800;
  static constexpr int kHeight = 600;

  Canvas();

  // ---- pixels
  static bool inside(int x, int y) { return x >= 0 && y >= 0 && x < kWidth && y < kHeight; }
  Colour at(int x, int y) const {
    return pixels_.empty() ? background_ : pixels_[static_cast<size_t>(y) * kWidth + static_cast<size_t>(x)];
  }
  /// Every pixel, row by row (the screen's memory is made on first use: see pixels_).
  const Pixels& pixels() const { return materialize(); }

  // ---- drawing state (setColor, lineWidth, gotoXY)
  Colour foreground = colours::kBlack;
  std::optional<Colour> textBackground;  ///< setColor's second colour: behind printed text
  int lineWidth = 1;
  Point pen;                             ///< where lineTo starts

  // ---- drawing commands
  void clear(Colour c);
  Colour background() const { return background_; }
  void setPixel(int x, int y, Colour c);
  void line(Point a, Point b, int width, Colour c);
  void rectangle(Point a, Point b, int width, std::optional<Colour> outline, std::optional<Colour> fill);
  void ellipse(Point a, Point b, int width, std::optional<Colour> outline, std::optional<Colour> fill);
  /// `afterEdge`, when given, is called after each edge of the outline: a wide outline of many
  /// long edges is slow work, and the caller may end it there (the run's limits).
  void polygon(const std::vector<Point>& pts, int width, std::optional<Colour> outline,
               std::optional<Colour> fill, const std::function<void()>& afterEdge = nullptr);
  void floodFill(int x, int y, Colour c);
  /// Draws text with the top-left corner of its first cell at (x, y); returns its width in
  /// pixels (the sum of the characters' advances).
  int text(int x, int y, const std::string& s, const TextStyle& style, Colour c);
  /// The fonts this screen draws with (created when text is first drawn).
  FontRenderer& fonts();
  /// `print`: text at the text cursor in the print font (TextStyle's default: 100 columns of
  /// 8 pixels, 40 lines of 15), wrapping at the right edge and scrolling at the bottom.
  void print(const std::string& s, bool newline);
  Point textCursor() const { return cursor_; }

  /// saveScr / restoreScr.
  void save();
  void restore();

  // ---- the robot's pen trail: a polyline that grows while the pen is down. It is one
  // continuous line: when something else was drawn since the last trailTo, the trail goes on
  // in a new display-list entry that starts where the last one ended. A straight segment of
  // the trail that repeats one already in the display list, in the same colour and width with
  // nothing else drawn since, is left out (the SVG's picture is the same: a trail is stroked with
  // round caps and joins, so it covers the union of its segments' strokes; see trailTo).
  void trailStart(double x, double y, int width, Colour c);
  void trailTo(double x, double y);
  void trailEnd() { trailOpen_ = false; }
  bool trailOpen() const { return trailOpen_; }
  int trailWidth() const { return trailWidth_; }
  Colour trailColour() const { return trailColour_; }

  // ---- obstacles: a pixel is an obstacle unless it has the background colour or an
  // invisible colour.
  void setInvisible(std::vector<Colour> colours);
  const std::vector<Colour>& invisible() const { return invisible_; }
  bool isObstacleColour(Colour c) const {
    if (c == background_) return false;
    for (Colour v : invisible_)
      if (v == c) return false;
    return true;
  }
  bool isObstacle(int x, int y) const { return !inside(x, y) || isObstacleColour(at(x, y)); }
  /// Changes whenever some pixel may have become, or stopped being, an obstacle.
  uint64_t obstacleVersion() const { return obstacleVersion_; }
  /// The obstacle changes since the last call, which forgets them.
  ChangeBoxes takeObstacleChanges() {
    ChangeBoxes c = obstacleChanges_;
    obstacleChanges_ = {};
    return c;
  }
  /// Changes whenever any pixel changes.
  uint64_t version() const { return version_; }
  /// Where pixels changed since trackDamage(true) or the last takeDamage(): a recording of the
  /// run encodes only that part of the screen. Not kept unless asked for.
  void trackDamage(bool on) {
    damageOn_ = on;
    damage_ = {};
    tracking_ = damageOn_ || changesOn_;
  }
  PixelBox takeDamage() {
    PixelBox d = damage_;
    damage_ = {};
    return d;
  }
  /// Where pixels changed, box by box, since trackChanges(true) (everything, at first) or the
  /// last takeChanges(): a grader's colour watch (record/colour_watch.h) looks again only
  /// there. Not kept unless asked for.
  void trackChanges(bool on) {
    changesOn_ = on;
    changes_ = {};
    changes_.all = on;
    tracking_ = damageOn_ || changesOn_;
  }
  /// Moves the changes into `into` (its boxes' memory is reused) and forgets them.
  void takeChanges(ChangeBoxes& into) {
    into.boxes.swap(changes_.boxes);
    changes_.boxes.clear();
    into.all = changes_.all;
    changes_.all = false;
  }

  /// The display list: what was drawn since the last clearScr, for the SVG writer. Kept only
  /// when asked for (rb render -o x.svg); a run that never writes an SVG keeps none, so its
  /// memory does not grow with what it draws. Straight stretches of the pen trail are kept as
  /// one segment, a trail segment retraced with nothing drawn in between is kept once, and a
  /// clearScr or a fill of the whole screen drops what it hides.
  void keepDisplayList(bool keep);
  const std::vector<DrawOp>& displayList() const { return ops_; }
  /// Whether text drawn again over itself paints only the characters that changed (see
  /// TextTrace; on by default). The pixels are the same either way: tests compare the two.
  void setTextMemory(bool on) {
    textMemory_ = on;
    if (!on) forgetAllTraces();
  }
  /// How far a point of the pen trail may lie from the straight segment that replaces it.
  static constexpr double kTrailTolerance = 0.5;

 private:
  void plot(int x, int y, Colour c) {
    if (!inside(x, y)) return;
    Colour& p = materialize()[static_cast<size_t>(y) * kWidth + static_cast<size_t>(x)];
    if (p == c) return;
    if (isObstacleColour(p) != isObstacleColour(c)) {
      ++obstacleVersion_;
      obstacleChanges_.add(x, y);
    }
    p = c;
    ++version_;
    if (tracking_) [[unlikely]] changed(y, x, x);
    if (liveTraces_ != 0) [[unlikely]] forgetTraces(y, x, x);
  }
  void brush(int x, int y, int width, Colour c);
  void span(int y, int x1, int x2, Colour c);
  /// A glyph's pixels, its bitmap's top-left corner at (left, top).
  void paintGlyph(const Glyph& g, int left, int top, Colour c);
  /// A character's cell x0..x0+w-1, rows y0..y0+h-1, painted with `background` and the glyph
  /// (whose bitmap lies inside the cell) at left, top in c: only the pixels that differ from
  /// what is there are written, so a digit that changed in a status line flips only the pixels
  /// of its two glyphs.
  void paintCell(int x0, int w, int y0, int h, Colour background, const Glyph& g, int left, int top, Colour c);
  /// Writes pixels px[0..n-1] at x..x+n-1 of row y (clipped), each only where it differs.
  void writeRow(int y, int x, const Colour* px, int n);
  /// The bookkeeping of a row whose pixels first..last changed, those firstFlip..lastFlip
  /// (firstFlip < 0: none) becoming or stopping being obstacles.
  void rowChanged(int y, int first, int last, int firstFlip, int lastFlip);
  void drawLine(Point a, Point b, int width, Colour c);  ///< without recording it
  void scrollUp(int pixels);
  /// Records the operation `make()` builds, when the display list is kept.
  template <typename Make>
  void record(Make make) {
    if (keepOps_) push(make());
  }
  void push(DrawOp op);
  /// The open trail's last segment is final (a corner follows it, or the trail ends): drops it
  /// when it repeats a segment of trailSeen_. Returns whether it was dropped.
  bool settleTrailSegment();
  /// Whether trailSeen_ still describes the display list's end (nothing else pushed since).
  bool trailSeenCurrent() const {
    return opsGeneration_ == trailSeenGeneration_ && !ops_.empty() && trailOp_ == ops_.size() - 1 &&
           ops_.back().kind == DrawOp::Trail;
  }
  void pushTrail(std::vector<Point> pts, bool keepSeen);

  /// What a recent text draw left on the screen: its characters were drawn at `at` in this
  /// style and colour, and no pixel in `box` has changed since. Drawing text again over it
  /// (a status line redrawn every step) paints only the characters that differ: a character
  /// drawn again where it already is, over pixels that have not changed, paints nothing new.
  struct TextTrace {
    bool live = false;
    Point at;
    TextStyle style;
    Colour colour = 0;
    std::string text;       ///< the characters drawn (those that start on the screen)
    std::vector<int> pens;  ///< where each of them starts
    PixelBox box;           ///< every pixel the draw may have painted: cells and glyphs
    bool inCells = false;   ///< no glyph reaches outside its own character cell
    uint64_t drawn = 0;     ///< when (textClock_), to replace the oldest
  };
  static constexpr size_t kMaxTraces = 4;
  static constexpr size_t kMaxTraceChars = 512;  ///< longer texts are not remembered
  std::array<TextTrace, kMaxTraces> traces_;
  int liveTraces_ = 0;
  uint64_t textClock_ = 0;
  bool textMemory_ = true;
  std::vector<const Glyph*> glyphScratch_;
  /// A pixel in row y between x1 and x2 changed: the traces whose box holds it are forgotten.
  void forgetTraces(int y, int x1, int x2);
  void forgetAllTraces() {
    for (TextTrace& t : traces_) t.live = false;
    liveTraces_ = 0;
  }

  /// The screen, row by row; empty until something is drawn or the pixels are asked for, and
  /// then every pixel is background_. A program that never draws never touches the 1.9 MB
  /// (mapping those pages cost more than the rest of an empty program's start-up).
  mutable Pixels pixels_;
  Pixels& materialize() const {
    if (pixels_.empty()) [[unlikely]] makePixels();
    return pixels_;
  }
  void makePixels() const;
  Pixels saved_;
  Colour background_ = colours::kWhite;
  std::vector<Colour> invisible_;
  uint64_t obstacleVersion_ = 1;
  ChangeBoxes obstacleChanges_{{}, true};  // at first, everything is new
  void obstaclesChangedEverywhere() {
    ++obstacleVersion_;
    obstacleChanges_.all = true;
  }
  uint64_t version_ = 1;
  bool tracking_ = false;  ///< damageOn_ or changesOn_
  bool damageOn_ = false;
  PixelBox damage_;
  bool changesOn_ = false;
  ChangeBoxes changes_;
  /// Pixels x1..x2 of row y changed: the damage and the change boxes, when kept.
  void changed(int y, int x1, int x2) {
    if (damageOn_) damage_.add(x1, y), damage_.add(x2, y);
    if (changesOn_) changes_.addRow(y, x1, x2);
  }
  /// Every pixel may have changed.
  void damageAll() {
    if (damageOn_) damage_.add(0, 0), damage_.add(kWidth - 1, kHeight - 1);
    if (changesOn_) changes_.all = true;
  }
  Point cursor_;  ///< text cursor in pixels (top-left of the next character)
  bool keepOps_ = false;
  std::vector<DrawOp> ops_;
  bool trailOpen_ = false;
  std::array<double, 2> trailEnd_{};     ///< the open trail's end, exactly
  // The straight stretch the trail's last display-list segment stands for (see trailTo).
  std::array<double, 2> trailAnchor_{};  ///< its first point: the last corner
  bool trailCone_ = false;
  double trailConeDir_ = 0, trailConeLo_ = 0, trailConeHi_ = 0;
  Point trailAt_;             ///< where the open trail ends
  int trailWidth_ = 1;
  Colour trailColour_ = 0;
  size_t trailOp_ = 0;        ///< the display-list entry the open trail last grew
  /// One straight segment of the trail, its ends in a fixed order (a segment is the same both
  /// ways).
  struct Segment {
    Point a, b;
    Segment(Point p, Point q) : a(p), b(q) {
      if (q.x < p.x || (q.x == p.x && q.y < p.y)) a = q, b = p;
    }
    friend bool operator==(const Segment&, const Segment&) = default;
  };
  struct SegmentHash {
    size_t operator()(const Segment& s) const {
      auto u = [](int v) { return static_cast<uint64_t>(static_cast<uint32_t>(v)); };
      uint64_t h = (u(s.a.x) << 32 | u(s.a.y)) * 0x9E3779B97F4A7C15ull;
      h ^= (u(s.b.x) << 32 | u(s.b.y)) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2);
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  /// The settled segments of the trail entries at the end of the display list, all in the
  /// trail's colour and width, with nothing else drawn since the first of them.
  std::unordered_set<Segment, SegmentHash> trailSeen_;
  uint64_t opsGeneration_ = 0;        ///< counts push(): anything added to the display list
  uint64_t trailSeenGeneration_ = ~uint64_t{0};  ///< opsGeneration_ when trailSeen_ was current
  std::unique_ptr<FontRenderer> fonts_;
};

}  // namespace rb
