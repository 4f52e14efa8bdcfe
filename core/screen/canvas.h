#pragma once
// The 800 x 600 screen. Every pixel keeps the colour number it was drawn with (0..15 for the
// palette, larger numbers for RGB() colours), so `rLook() = RED` compares exactly. Drawing is
// exact and deterministic (no anti-aliasing): the robot's sensors read these pixels.
//
// Besides the pixels the canvas keeps a display list of what was drawn, so that the SVG writer
// can emit real vector elements, and it tracks which pixels are obstacles for the robot
// (neither the background colour nor an invisible colour) so that the simulator knows when its
// obstacle map must be rebuilt.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "screen/font.h"

namespace rb {

/// A colour number: 0..15 the palette, otherwise r + 256*g + 65536*b as RGB() makes it.
using Colour = uint32_t;

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
  Colour at(int x, int y) const { return pixels_[static_cast<size_t>(y) * kWidth + static_cast<size_t>(x)]; }
  const std::vector<Colour>& pixels() const { return pixels_; }

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
  void polygon(const std::vector<Point>& pts, int width, std::optional<Colour> outline,
               std::optional<Colour> fill);
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
  // in a new display-list entry that starts where the last one ended.
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
  /// Changes whenever any pixel changes.
  uint64_t version() const { return version_; }

  const std::vector<DrawOp>& displayList() const { return ops_; }

 private:
  void plot(int x, int y, Colour c) {
    if (!inside(x, y)) return;
    Colour& p = pixels_[static_cast<size_t>(y) * kWidth + static_cast<size_t>(x)];
    if (p == c) return;
    if (isObstacleColour(p) != isObstacleColour(c)) ++obstacleVersion_;
    p = c;
    ++version_;
  }
  void brush(int x, int y, int width, Colour c);
  void span(int y, int x1, int x2, Colour c);
  void scrollUp(int pixels);
  void record(DrawOp op);

  std::vector<Colour> pixels_;
  std::vector<Colour> saved_;
  Colour background_ = colours::kWhite;
  std::vector<Colour> invisible_;
  uint64_t obstacleVersion_ = 1;
  uint64_t version_ = 1;
  Point cursor_;  ///< text cursor in pixels (top-left of the next character)
  std::vector<DrawOp> ops_;
  bool trailOpen_ = false;
  Point trailAt_;             ///< where the open trail ends
  int trailWidth_ = 1;
  Colour trailColour_ = 0;
  size_t trailOp_ = 0;        ///< the display-list entry the open trail last grew
  std::unique_ptr<FontRenderer> fonts_;
};

}  // namespace rb
