#pragma once
// Where the parts of `rb run --tui` go on a terminal of a given size, how arena cells map to
// screen pixels and back, and the text of the status panel. Pure functions, tested without a
// terminal; tui/tui_host.cpp draws with them.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rb::tui {

struct Rect {
  int col = 0, row = 0, width = 0, height = 0;
  bool contains(int c, int r) const {
    return c >= col && r >= row && c < col + width && r < row + height;
  }
};

struct TuiLayout {
  bool tooSmall = false;  ///< below kMinCols x kMinRows: only a message fits
  Rect title;             ///< the top line
  Rect arenaBox;          ///< the arena with its border
  Rect arena;             ///< the arena's cells: 800 x 600 pixels scaled to fit, about 4:3
  Rect status;            ///< the status lines: beside the arena, or under it when narrow
  Rect sourceBox;         ///< the program around the running line, with its border
  Rect source;            ///< inside sourceBox
  Rect varsBox;           ///< the variables, with its border (empty when there is no room)
  Rect vars;              ///< inside varsBox
  Rect output;            ///< what the program prints (its header line included)
  Rect keys;              ///< the bottom line: rb's keys
};

constexpr int kMinCols = 40;
constexpr int kMinRows = 12;
/// The status panel's lines when it has room for all of them (a real robot adds kLinkRows).
constexpr int kStatusRows = 9;
constexpr int kLinkRows = 3;

/// Lays out a terminal of cols x rows cells. With room (72 columns or more) the arena is on the
/// left with the output under it, and the status, source and variables panes on the right;
/// narrower, everything is stacked and the variables pane is left out. The status panel gets
/// `statusRows` rows beside the arena when 12 rows are left for the source and variables, else
/// three (its compact form).
TuiLayout layoutTui(int cols, int rows, int statusRows = kStatusRows);

/// The screen pixel shown at the centre of an arena cell (terminal coordinates), clamped to the
/// 800 x 600 screen when the cell is outside the arena.
std::pair<int, int> cellToPixel(const Rect& arena, int col, int row);
/// The terminal cell that shows a screen pixel.
std::pair<int, int> pixelToCell(const Rect& arena, int x, int y);
/// The screen pixels an arena cell shows (x, y, width, height in pixels): exactly the pixels
/// that pixelToCell maps to that cell.
Rect cellPixels(const Rect& arena, int col, int row);
/// The arena cells that show some pixel of the screen area [x, x + w) x [y, y + h), clipped to
/// the arena; empty when the area is off the screen.
Rect cellsShowing(const Rect& arena, int x, int y, int w, int h);

/// What the status panel shows.
struct TuiStatus {
  std::string state;       ///< "running", "paused", "waiting for a key", ...
  double speedFactor = 1;  ///< the view's speed-up (F4/F5, --speed)
  double rSpeed = 0;       ///< the program's rSpeed
  bool located = false;
  double x = 0, y = 0, heading = 0;
  bool pen = false;
  int bumper = 0, feel = 0;
  bool sensors = true;     ///< false: the bumper and feel bits are not known (an earlier step)
  std::optional<double> range;  ///< the last rRange reading
  // A real robot (--real, rCommPort): what its link did.
  bool real = false;
  std::string port;        ///< the device
  uint64_t commands = 0;   ///< commands sent
  std::string lastReply;   ///< the last reply, as the status shows it ("" before any)
};

/// The status panel's lines (kStatusRows, or more for a real robot), each at most `width`
/// characters: "label   value".
std::vector<std::string> statusLines(const TuiStatus& s, int width);
/// The same in at most three lines, for a short panel or a narrow terminal.
std::vector<std::string> compactStatusLines(const TuiStatus& s, int width);
/// What the view is doing, for the keys it offers.
enum class ViewState {
  Running,
  Paused,
  Ended,  ///< the run is over: only what can still be done (restart, the view, quitting)
  NotLoaded,  ///< the program has errors: restart (load it again) or quit
  BackPaused,  ///< paused, showing an earlier step
  BackEnded,   ///< after the end, showing an earlier step
};
/// The bottom line: rb's keys for `state`, as many as fit in `width`; `watching` (--watch)
/// adds that a save restarts.
std::string keysLine(int width, ViewState state, bool programKeys, bool watching = false);
/// The bits of rBumper() or rFeel() in words: "4 front", "0", "6 right+front".
std::string bumperText(int bits);
std::string feelText(int bits);
/// "x1", "x4", "x1/2".
std::string speedText(double factor);

}  // namespace rb::tui
