#pragma once
// The text of the live view's source and variables panes: pure functions, tested without a
// terminal; tui/tui_host.cpp draws them.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "base/source.h"
#include "machine/interpreter.h"

namespace rb::tui {

/// One line of a pane.
struct PaneLine {
  std::string text;
  bool highlight = false;  ///< the line running now
  bool marked = false;     ///< a breakpoint is on it
  bool error = false;      ///< the run's error is on it (after the end)
};

/// The lines of `file` around `line` (the statement about to run; 0: none yet) for a pane of
/// `height` rows and `width` columns. Each is a marker column ('>' the running line, '*' a
/// breakpoint), the line number and the text, tabs expanded, cut at `width`. The running line
/// stays about a third of the way down. `hasBreakpoint(line)` tells which lines are marked.
/// `running` false (the run is over): the pane stays where it was, but no line is marked
/// running.
template <typename HasBreakpoint>
std::vector<PaneLine> sourceLines(const SourceFile& file, uint32_t line, int height, int width,
                                  HasBreakpoint hasBreakpoint, bool running = true, uint32_t errorLine = 0);

/// The variables pane's lines, `width` columns each: "name  value", names padded to a column;
/// strings in quotes, arrays as `name[3,4]` and their first elements; a variable without a value
/// yet as "-". Locals of the running sub `sub` follow the globals under a header line.
std::vector<std::string> variableLines(const std::vector<VariableView>& vars, std::string_view sub,
                                       int width);

/// A watch as the variables pane shows it: its expression and its value (as valueText shows
/// it) or why it has none.
struct WatchLine {
  std::string expr;
  std::string value;  ///< valueText of the value, or the error
  bool error = false;
};
/// The watches' lines at the top of the variables pane, `width` columns each: a header, then
/// "x * 2 = 14" for each, or "a[9] + 1: index 9 is out of range ..." with an error wrapped
/// onto indented lines so that it is read whole. Nothing when there are no watches.
std::vector<std::string> watchLines(const std::vector<WatchLine>& watches, int width);

/// A value as the variables pane shows it, at most `width` characters (0: no limit).
std::string valueText(const Value& v, size_t width);

/// Tab stops of the output pane: every 8 columns, as a terminal sets them.
constexpr size_t kOutputTab = 8;

/// One line of program output as terminal cells: each tab becomes the spaces to the next tab
/// stop (kOutputTab), other control characters '?' (a byte is a cell, as the screen draws it).
std::string outputCells(std::string_view line);
/// A line cut into rows of `width` cells (at least one row, "" for an empty line), after
/// outputCells: nothing of a long line is lost.
std::vector<std::string> wrapRows(std::string_view line, int width);
/// As wrapRows, but each row ends at a space when the line goes on (a message read as text:
/// words are not cut, unless one is longer than a row); the spaces where rows break are dropped.
std::vector<std::string> wordRows(std::string_view line, int width);
/// The last `rows` rows that `lines` (oldest first) take in a pane `width` cells wide, each line
/// wrapped by wrapRows; fewer when they take fewer.
std::vector<std::string> lastRows(const std::vector<std::string_view>& lines, int width, int rows);

// ---- the template's body

/// One source line as a pane shows it.
std::string paneLineText(std::string_view text, uint32_t number, int numberWidth, char marker,
                         int width);

template <typename HasBreakpoint>
std::vector<PaneLine> sourceLines(const SourceFile& file, uint32_t line, int height, int width,
                                  HasBreakpoint hasBreakpoint, bool running, uint32_t errorLine) {
  std::vector<PaneLine> out;
  if (height <= 0 || width <= 0) return out;
  uint32_t count = file.lineCount();
  uint32_t rows = static_cast<uint32_t>(height);
  uint32_t first = 1;
  if (line > rows / 3) first = line - rows / 3;
  if (count >= rows && first > count - rows + 1) first = count - rows + 1;
  if (first < 1) first = 1;
  int numberWidth = static_cast<int>(std::to_string(count).size());
  for (uint32_t n = first; n < first + rows && n <= count; ++n) {
    PaneLine l;
    l.highlight = running && n == line;
    l.marked = hasBreakpoint(n);
    l.error = n == errorLine;
    char marker = l.highlight ? '>' : l.error ? '!' : l.marked ? '*' : ' ';
    l.text = paneLineText(file.lineText(n), n, numberWidth, marker, width);
    out.push_back(std::move(l));
  }
  return out;
}

}  // namespace rb::tui
