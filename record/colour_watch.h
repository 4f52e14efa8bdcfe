#pragma once
// What the robot's disc covers as it moves, for the colours a grader watches (`avoid` and
// `touch` checks with `colour =`, docs/teaching.md). The rule:
//
// - Each rLocate, move and crash takes the robot's centre from where the last of them left it
//   (an rLocate: from where it places the robot) to where it is now, on n + 1 points k / n of
//   the way (k = 0..n, n = the length rounded up, at least 1): at most 1 px apart.
// - At each point c, a pixel (x, y) of the screen is under the disc of radius r when
//   coverDistance2(x, y, c) <= r * r. The screen is the one the event leaves.
// - A colour (0xRRGGBB, compared as the screen shows it) is touched at the first point whose disc
//   covers a pixel of it; while the pen is down, pixels of the trail's colour do not count. The
//   first touch is kept, with the line of the statement (0: another file).
//
// Checking that rule pixel by pixel reads the whole disc (1,257 pixels at radius 20) at every
// point: grading took 6 to 16 times the processor time of a region check (bench/grade/colour.sh),
// enough for the time limit rather than the step limit to stop an endless program. The watch
// gets the same answers from far less:
//
// - It keeps, for each colour, which pixels have it: a bit per pixel, 64 to a cell of 8 x 8, and
//   for each block of 4 x 4 cells the count of those bits. The screen tells it where pixels
//   changed (Canvas::trackChanges); a small change is read at once, pixel by pixel, a large one
//   (or clearScr) only marks its cells unread, and a cell is read again when a search comes
//   near it.
// - For each colour it keeps a clear disc: a centre and a radius within which no pixel has the
//   colour and no cell is unread. A disc of the robot inside it covers nothing of the colour, so
//   the points of a move inside it are passed over. Where a point's disc is not inside it, a
//   search for the colour's nearest pixel (blocks and cells nearest first, empty ones passed
//   over, eight bits of a row at a time) decides that point exactly, and its result is the next
//   clear disc. Far from the colour one search clears hundreds of pixels of travel; along a
//   wall, as far as the robot is from the wall.
// - A colour once touched is no longer looked at.

#include <cstdint>
#include <optional>
#include <vector>

#include "geometry.h"
#include "machine/machine.h"
#include "record.h"
#include "screen/canvas.h"

namespace rb::record {

/// The squared distance from pixel (x, y) to a point c of the robot's path, as the rule measures
/// it: the pixel lies under the disc of radius r there when this is at most r * r.
inline double coverDistance2(int x, int y, P2 c) {
  const double dx = x - c.x, dy = y - c.y;
  return dx * dx + dy * dy;
}

class ColourWatch {
 public:
  /// Watches `colours` (0xRRGGBB; one Touch each, in this order) on `canvas`, which must outlive
  /// the watch: from now on the canvas keeps its change boxes for it.
  ColourWatch(Canvas& canvas, const std::vector<uint32_t>& colours);
  ~ColourWatch();
  ColourWatch(const ColourWatch&) = delete;
  ColourWatch& operator=(const ColourWatch&) = delete;

  /// The robot is already at `p` (a world program placed it): the next move starts there. That
  /// point itself is looked at with the move.
  void startAt(P2 p);
  /// rLocate, a move or a crash: the disc of `radius` along the way (the rule above). Other
  /// events change nothing.
  void robotEvent(const RobotEvent& e, double radius);
  /// One sweep from `from` to `to` (equal: the one point), with the pen's trail colour when the
  /// pen is down.
  void sweep(P2 from, P2 to, double radius, std::optional<uint32_t> ownRgb, uint32_t line);

  const std::vector<RunRecord::Touch>& touches() const { return touches_; }

  /// The work done so far, for tests: searches for a nearest pixel, and cells read from the
  /// screen.
  uint64_t searches() const { return searches_; }
  uint64_t cellsRead() const { return cellsRead_; }

 private:
  static constexpr int kCell = 8;  ///< a cell is kCell x kCell pixels, one bit each
  static constexpr int kCellsX = Canvas::kWidth / kCell, kCellsY = Canvas::kHeight / kCell;
  static constexpr int kBlock = 4;  ///< a block is kBlock x kBlock cells
  static constexpr int kBlocksX = (kCellsX + kBlock - 1) / kBlock, kBlocksY = (kCellsY + kBlock - 1) / kBlock;
  static_assert(Canvas::kWidth % kCell == 0 && Canvas::kHeight % kCell == 0);

  /// One colour watched (distinct colours: a colour given twice shares one).
  struct Watched {
    uint32_t rgb = 0;
    bool done = false;              ///< touched: no longer looked at, nor kept
    std::vector<uint64_t> bits;     ///< per cell: its pixels of the colour, bit 8 * row + column
    std::vector<uint16_t> inBlock;  ///< per block: the bits set in its read cells
    /// The clear disc: no pixel of the colour and no unread cell closer than `clear` to `at`.
    P2 at;
    double clear = 0;
    double reach = 0;  ///< how far beyond the robot's radius the next search looks
  };

  /// Takes the screen's changes since the last sweep.
  void takeChanges();
  /// Reads the pixels of `box` (on the screen) again, one by one.
  void readPixels(const PixelBox& box);
  /// Marks the cells `box` meets unread.
  void markUnread(const PixelBox& box);
  void markAllUnread();
  /// Reads an unread cell.
  void readCell(int cell);
  /// Which watched colour a screen colour is (watched_.size(): none).
  size_t indexOf(Colour c) {
    if (c != lastColour_) {
      lastColour_ = c;
      lastIndex_ = watched_.size();
      const uint32_t rgb = colourToRgb(c);
      for (size_t i = 0; i < watched_.size(); ++i)
        if (watched_[i].rgb == rgb) lastIndex_ = i;
    }
    return lastIndex_;
  }
  /// The first point of the sweep whose disc covers a pixel of `w`, or -1.
  long firstCover(Watched& w, P2 from, P2 to, int n, double radius);
  /// The squared distance from `c` to the nearest pixel of `w` or unread cell, searched up to
  /// radius + w.reach (its square when nothing is nearer); exact when at most radius squared.
  double nearest(Watched& w, P2 c, double radius);

  Canvas& canvas_;
  std::vector<Watched> watched_;
  std::vector<size_t> watchedOf_;  ///< per touch: its colour in watched_
  std::vector<RunRecord::Touch> touches_;
  size_t active_ = 0;                   ///< colours not yet touched
  std::vector<uint8_t> unread_;         ///< per cell: changed since it was read
  std::vector<uint16_t> unreadInBlock_;  ///< per block: its unread cells
  ChangeBoxes changes_;                 ///< scratch: the screen's change boxes
  uint64_t seenVersion_ = 0;            ///< the screen's version when its changes were last taken
  std::vector<uint64_t> cellBits_;      ///< scratch: one cell's bits per colour
  struct Near {
    double d2;
    int block;
  };
  std::vector<Near> near_;  ///< scratch: the blocks a search looks at, nearest first
  Colour lastColour_ = ~Colour{0};
  size_t lastIndex_ = 0;
  P2 last_;
  bool placed_ = false;
  uint64_t searches_ = 0, cellsRead_ = 0;
};

}  // namespace rb::record
