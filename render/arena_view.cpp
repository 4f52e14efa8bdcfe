#include "arena_view.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <span>
#include <string_view>

#include "robot/robot_sim.h"
#include "robot_image.h"

namespace rb::render {

namespace {

constexpr int kScreenW = Canvas::kWidth;
constexpr int kScreenH = Canvas::kHeight;

// The half blocks: upper (U+2580), lower (U+2584) and full (U+2588).
constexpr const char* kUpperHalf = "\u2580";
constexpr const char* kLowerHalf = "\u2584";
constexpr const char* kFullBlock = "\u2588";

// The robot's heading in eight 45-degree sectors, clockwise from up. The ASCII glyphs cannot
// tell a diagonal from its opposite; the arrows of the UTF-8 modes can.
constexpr const char* kAsciiHeading[8] = {"^", "/", ">", "\\", "v", "/", "<", "\\"};
constexpr const char* kArrowHeading[8] = {"\u2191", "\u2197", "\u2192", "\u2198",
                                          "\u2193", "\u2199", "\u2190", "\u2196"};

/// Sets a cell's glyph. Building a new string and moving it in (rather than assigning the
/// characters) sidesteps a false -Wrestrict of GCC 12 on std::string::assign at -O3.
void setGlyph(Cell& cell, std::string_view glyph) { cell.glyph = std::string(glyph); }

/// The ASCII density ramp: a cell with any drawn pixel is at least '.', so thin lines stay
/// visible however small a part of the cell they cover.
struct RampStep {
  double below;  ///< coverage (drawn pixels / block pixels) under which this glyph applies
  const char* glyph;
};
constexpr RampStep kRamp[] = {{0.125, "."}, {0.30, ":"}, {0.55, "+"}, {0.80, "*"}, {2.0, "#"}};

/// Counts the drawn (non-background) pixels of a block and the few colours among them, so the
/// dominant colour can be picked without a map per cell. Colours beyond kSlots distinct ones
/// still count as drawn but cannot become dominant, which keeps the result deterministic.
struct Tally {
  static constexpr int kSlots = 6;
  Colour colour[kSlots] = {};
  uint32_t count[kSlots] = {};
  int used = 0;
  uint32_t drawn = 0;   ///< non-background pixels
  uint32_t pixels = 0;  ///< all pixels of the block

  void add(Colour c, uint32_t n) {
    drawn += n;
    for (int i = 0; i < used; ++i)
      if (colour[i] == c) {
        count[i] += n;
        return;
      }
    if (used < kSlots) {
      colour[used] = c;
      count[used] = n;
      ++used;
    }
  }
  void merge(const Tally& other) {
    pixels += other.pixels;
    uint32_t listed = 0;
    for (int i = 0; i < other.used; ++i) {
      add(other.colour[i], other.count[i]);
      listed += other.count[i];
    }
    drawn += other.drawn - listed;  // pixels of colours the other tally could not list
  }
  bool any() const { return drawn > 0; }
  /// The most frequent drawn colour (the first seen on a tie); only valid when any().
  Colour dominant() const {
    int best = 0;
    for (int i = 1; i < used; ++i)
      if (count[i] > count[best]) best = i;
    return used > 0 ? colour[best] : colour[0];
  }
};

/// The pixel range [first, last) of block `i` of `n` across `size` pixels. Blocks never get
/// empty: when there are more blocks than pixels, neighbours share a pixel.
struct Range {
  int first, last;
};
Range blockRange(int i, int n, int size) {
  int first = static_cast<int>(static_cast<int64_t>(i) * size / n);
  int last = static_cast<int>(static_cast<int64_t>(i + 1) * size / n);
  first = std::min(first, size - 1);
  last = std::max(last, first + 1);
  return {first, last};
}

/// The block of `n` across `size` pixels that holds pixel `p` (the inverse of blockRange).
int blockOf(int p, int n, int size) {
  int64_t b = (static_cast<int64_t>(p + 1) * n - 1) / size;
  return static_cast<int>(std::clamp<int64_t>(b, 0, n - 1));
}

/// Tallies one block of the screen. Runs of equal pixels on a row are counted at once, since
/// drawings are mostly long runs of one colour.
Tally tallyBlock(std::span<const Colour> pixels, Colour background, Range xs, Range ys) {
  Tally t;
  t.pixels = static_cast<uint32_t>((xs.last - xs.first) * (ys.last - ys.first));
  for (int y = ys.first; y < ys.last; ++y) {
    const Colour* row = pixels.data() + static_cast<size_t>(y) * kScreenW;
    int x = xs.first;
    while (x < xs.last) {
      Colour c = row[x];
      int run = 1;
      while (x + run < xs.last && row[x + run] == c) ++run;
      if (c != background) t.add(c, static_cast<uint32_t>(run));
      x += run;
    }
  }
  return t;
}

const char* asciiGlyph(const Tally& t) {
  if (!t.any()) return " ";
  double coverage = static_cast<double>(t.drawn) / t.pixels;
  for (const RampStep& step : kRamp)
    if (coverage < step.below) return step.glyph;
  return kRamp[std::size(kRamp) - 1].glyph;
}

/// U+2800 + bits as UTF-8 (bits: dots 1-8 as the braille block numbers them).
std::string brailleGlyph(unsigned bits) {
  std::string s(3, '\0');
  s[0] = static_cast<char>(0xE2);
  s[1] = static_cast<char>(0xA0 + (bits >> 6));
  s[2] = static_cast<char>(0x80 + (bits & 0x3F));
  return s;
}

/// The bit of the braille dot in column dx (0..1), row dy (0..3) of a cell.
unsigned brailleBit(int dx, int dy) {
  // Dots 1-3 and 4-6 run down the two columns; dots 7 and 8 are the bottom row, added later.
  static constexpr unsigned kBits[4][2] = {{0x01, 0x08}, {0x02, 0x10}, {0x04, 0x20}, {0x40, 0x80}};
  return kBits[dy][dx];
}

/// Which of the eight 45-degree sectors a heading points into (0 = up, clockwise).
int headingSector(double heading) {
  if (!std::isfinite(heading)) return 0;
  double d = normalizeDegrees(heading);
  return static_cast<int>(std::lround(d / 45.0)) % 8;
}

void placeRobotGlyph(ArenaFrame& frame, uint32_t backgroundRgb, const RobotView& robot, CellMode mode) {
  if (!robot.visible || !std::isfinite(robot.x) || !std::isfinite(robot.y)) return;
  long px = std::lround(robot.x), py = std::lround(robot.y);
  if (px < 0 || py < 0 || px >= kScreenW || py >= kScreenH) return;
  int col = blockOf(static_cast<int>(px), frame.cols, kScreenW);
  int row = blockOf(static_cast<int>(py), frame.rows, kScreenH);
  int sector = headingSector(robot.heading);
  Cell& cell = frame.at(col, row);
  setGlyph(cell, mode == CellMode::Ascii ? kAsciiHeading[sector] : kArrowHeading[sector]);
  cell.fg = colourToRgb(robot.colour);
  cell.bg = backgroundRgb;
}

/// How far back in the display list text is looked for (a long list of trail segments after
/// the text costs no more than this per frame).
constexpr size_t kTextLookBack = 20000;

/// A character as UTF-8 for a cell ("" for one that shows nothing): ASCII as it is, Latin-1
/// letters as their UTF-8 form.
std::string cellCharacter(unsigned char c) {
  if (c > 32 && c < 127) return std::string(1, static_cast<char>(c));
  if (c >= 0xA1) {
    std::string s;
    s += static_cast<char>(0xC0 | (c >> 6));
    s += static_cast<char>(0x80 | (c & 0x3F));
    return s;
  }
  return "";
}

void overlayText(ArenaFrame& frame, const std::vector<DrawOp>& ops,
                 std::span<const Colour> pixels, Colour background) {
  if (frame.cols <= 0 || frame.rows <= 0) return;
  size_t from = ops.size();
  while (from > 0 && ops.size() - from < kTextLookBack) {
    DrawOp::Kind k = ops[from - 1].kind;
    if (k == DrawOp::Clear || k == DrawOp::Raster) break;
    --from;
  }
  const double cellW = static_cast<double>(kScreenW) / frame.cols;
  const double cellH = static_cast<double>(kScreenH) / frame.rows;
  // A character's cell: the one under the centre of its box.
  struct Placed {
    int col, row;
    std::string glyph;
    Colour colour, background;
  };
  std::vector<Placed> placed;
  for (size_t i = from; i < ops.size(); ++i) {
    const DrawOp& op = ops[i];
    if (op.kind != DrawOp::Text || op.text.empty() || op.points.size() < 2) continue;
    const int x0 = op.points[0].x, y0 = op.points[0].y, y1 = op.points[1].y;
    const double advance = static_cast<double>(op.points[1].x - x0) / static_cast<double>(op.text.size());
    if (advance < kReadableCells * cellW || (y1 - y0) < kReadableCells * cellH) continue;
    const int row = static_cast<int>(std::floor((y0 + y1) / 2.0 / cellH));
    if (row < 0 || row >= frame.rows) continue;
    for (size_t k = 0; k < op.text.size(); ++k) {
      const int bx0 = static_cast<int>(std::floor(x0 + advance * static_cast<double>(k)));
      const int bx1 = static_cast<int>(std::floor(x0 + advance * static_cast<double>(k + 1)));
      const int col = static_cast<int>(std::floor((bx0 + bx1) / 2.0 / cellW));
      if (col < 0 || col >= frame.cols) continue;
      // Still shown? Some pixel of the character's box has its colour; the most common other
      // colour there is the cell's background.
      Tally around;
      bool shows = false;
      for (int y = std::max(y0, 0); y < std::min(y1, kScreenH); ++y)
        for (int x = std::max(bx0, 0); x < std::min(bx1, kScreenW); ++x) {
          Colour c = pixels[static_cast<size_t>(y) * kScreenW + static_cast<size_t>(x)];
          if (c == op.colour) shows = true;
          else around.add(c, 1);
        }
      if (!shows) continue;
      Colour bg = around.any() ? around.dominant() : background;
      placed.push_back({col, row, cellCharacter(static_cast<unsigned char>(op.text[k])), op.colour, bg});
      // The other cells whose centres the character's box covers show its background: the
      // pixels of the glyph are shown by the character itself.
      for (int r = 0; r < frame.rows; ++r) {
        const double cy = (r + 0.5) * cellH;
        if (cy < y0 || cy >= y1) continue;
        for (int c = 0; c < frame.cols; ++c) {
          const double cx = (c + 0.5) * cellW;
          if (cx < bx0 || cx >= bx1) continue;
          placed.push_back({c, r, "", op.colour, bg});
        }
      }
    }
  }
  // Blanks first, so that a neighbour's blank never covers a character.
  for (int pass = 0; pass < 2; ++pass)
    for (const Placed& p : placed) {
      if (p.glyph.empty() != (pass == 0)) continue;
      Cell& cell = frame.at(p.col, p.row);
      setGlyph(cell, p.glyph.empty() ? std::string(" ") : p.glyph);
      cell.fg = colourToRgb(p.colour);
      cell.bg = colourToRgb(p.background);
    }
}

}  // namespace

ArenaFrame renderArena(const Pixels& screenPixels, Colour background, const RobotView& robot,
                       const ArenaOptions& options) {
  // The robot's image (robot_image.h) is drawn into a copy of the screen at scale 1, so its
  // ring and heading line fill cells like any drawing; its heading glyph goes on top at the end.
  const RobotImage robotImage(robot);
  std::vector<Colour> withRobot;  // heap memory: made again for every frame (base/large_memory.h)
  if (!robotImage.empty() && screenPixels.size() >= static_cast<size_t>(kScreenW) * kScreenH) {
    withRobot.assign(screenPixels.begin(), screenPixels.end());
    robotImage.rasterize(1, kScreenW, kScreenH, [&](int x, int y) {
      withRobot[static_cast<size_t>(y) * kScreenW + static_cast<size_t>(x)] = robot.colour;
    });
  }
  const std::span<const Colour> pixels = withRobot.empty() ? std::span<const Colour>(screenPixels) : std::span<const Colour>(withRobot);
  ArenaFrame frame;
  frame.cols = std::max(options.cols, 0);
  frame.rows = std::max(options.rows, 0);
  const uint32_t bgRgb = colourToRgb(background);
  Cell blank;
  blank.bg = bgRgb;
  frame.cells.assign(static_cast<size_t>(frame.cols) * frame.rows, blank);
  if (frame.cells.empty() || pixels.size() < static_cast<size_t>(kScreenW) * kScreenH) return frame;

  // Sub-samples per cell: 1 x 1 (ASCII), 1 x 2 (half blocks) or 2 x 4 (braille).
  const int sx = options.mode == CellMode::Braille ? 2 : 1;
  const int sy = options.mode == CellMode::Braille ? 4 : options.mode == CellMode::HalfBlock ? 2 : 1;
  const int subCols = frame.cols * sx, subRows = frame.rows * sy;

  // The column ranges are the same on every row: compute them once.
  std::vector<Range> xRanges(static_cast<size_t>(subCols));
  for (int i = 0; i < subCols; ++i) xRanges[static_cast<size_t>(i)] = blockRange(i, subCols, kScreenW);

  std::vector<Tally> samples(static_cast<size_t>(sx * sy));
  for (int row = 0; row < frame.rows; ++row) {
    for (int col = 0; col < frame.cols; ++col) {
      for (int dy = 0; dy < sy; ++dy) {
        Range ys = blockRange(row * sy + dy, subRows, kScreenH);
        for (int dx = 0; dx < sx; ++dx)
          samples[static_cast<size_t>(dy * sx + dx)] =
              tallyBlock(pixels, background, xRanges[static_cast<size_t>(col * sx + dx)], ys);
      }
      Cell& cell = frame.at(col, row);
      switch (options.mode) {
        case CellMode::Ascii: {
          const Tally& t = samples[0];
          setGlyph(cell, asciiGlyph(t));
          if (t.any()) cell.fg = colourToRgb(t.dominant());
          break;
        }
        case CellMode::HalfBlock: {
          const Tally& top = samples[0];
          const Tally& bottom = samples[1];
          if (top.any() && bottom.any()) {
            Colour a = top.dominant(), b = bottom.dominant();
            cell.fg = colourToRgb(a);
            if (a == b) {
              setGlyph(cell, kFullBlock);
            } else {
              // Two colours: the upper half in the foreground, the lower in the background.
              setGlyph(cell, kUpperHalf);
              cell.bg = colourToRgb(b);
            }
          } else if (top.any()) {
            setGlyph(cell, kUpperHalf);
            cell.fg = colourToRgb(top.dominant());
          } else if (bottom.any()) {
            setGlyph(cell, kLowerHalf);
            cell.fg = colourToRgb(bottom.dominant());
          }
          break;
        }
        case CellMode::Braille: {
          unsigned bits = 0;
          Tally whole;
          for (int dy = 0; dy < sy; ++dy)
            for (int dx = 0; dx < sx; ++dx) {
              const Tally& t = samples[static_cast<size_t>(dy * sx + dx)];
              if (t.any()) bits |= brailleBit(dx, dy);
              whole.merge(t);
            }
          if (bits != 0) {
            setGlyph(cell, brailleGlyph(bits));
            cell.fg = colourToRgb(whole.dominant());
          }
          break;
        }
      }
    }
  }
  if (options.textOps) overlayText(frame, *options.textOps, screenPixels, background);
  placeRobotGlyph(frame, bgRgb, robot, options.mode);
  return frame;
}

std::string frameText(const ArenaFrame& frame) {
  std::string out;
  out.reserve(static_cast<size_t>(frame.cols + 1) * frame.rows);
  for (int row = 0; row < frame.rows; ++row) {
    for (int col = 0; col < frame.cols; ++col) out += frame.at(col, row).glyph;
    out += '\n';
  }
  return out;
}

}  // namespace rb::render
