#include "tui_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string_view>

#include "screen/canvas.h"

namespace rb::tui {

namespace {

/// A terminal cell is about twice as tall as it is wide, so the 4:3 screen needs 8/3 as many
/// columns as rows (in every cell mode: half blocks and braille split cells into square dots).
constexpr double kColsPerRow = 8.0 / 3.0;
constexpr int kPanelWidth = 30;
constexpr int kMaxPanelWidth = 60;
constexpr int kMinArenaCols = 40;
constexpr int kOutputMinLines = 3;

std::string fixed1(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  std::string s = buf;
  return s == "-0.0" ? "0.0" : s;
}

/// A whole number plainly, anything else with one decimal.
std::string number(double v) {
  if (v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return fixed1(v);
}

/// Joins pieces by appending: GCC 12 warns falsely (-Wrestrict) about some `"a" + string` sums.
std::string join(std::initializer_list<std::string_view> parts) {
  std::string s;
  for (std::string_view p : parts) s.append(p);
  return s;
}

std::string bitsText(int bits, const int* values, const char* const* names, int n) {
  std::string s = std::to_string(bits);
  bool first = true;
  for (int i = 0; i < n; ++i) {
    if (!(bits & values[i])) continue;
    s.push_back(first ? ' ' : '+');
    s.append(names[i]);
    first = false;
  }
  return s;
}

}  // namespace

TuiLayout layoutTui(int cols, int rows, int statusRows) {
  TuiLayout l;
  if (cols < kMinCols || rows < kMinRows) {
    l.tooSmall = true;
    return l;
  }
  l.title = {0, 0, cols, 1};
  l.keys = {0, rows - 1, cols, 1};
  int bottom = rows - 1;  // the first row of the keys line
  bool side = cols - kPanelWidth - 2 >= kMinArenaCols;
  if (side) {
    // The panel takes about two fifths of a wide terminal, the arena the rest.
    int panel = std::clamp(cols * 2 / 5, kPanelWidth, kMaxPanelWidth);
    int innerW = cols - 2 - panel;
    int innerHMax = bottom - 1 - 2 - (1 + kOutputMinLines);
    int arenaRows = std::max(std::min(innerHMax, static_cast<int>(innerW / kColsPerRow)), 3);
    int arenaCols = std::min(innerW, static_cast<int>(std::lround(arenaRows * kColsPerRow)));
    l.arenaBox = {0, 1, arenaCols + 2, arenaRows + 2};
    l.arena = {1, 2, arenaCols, arenaRows};
    int below = l.arenaBox.row + l.arenaBox.height;
    l.output = {0, below, l.arenaBox.width, bottom - below};
    // The panel: status, then the source and the variables in boxes.
    int col = l.arenaBox.width + 1, width = cols - col, top = 1, height = bottom - top;
    int status = height >= statusRows + 12 ? statusRows : 3;
    l.status = {col, top, width, status};
    int rest = height - status;
    int source = rest >= 10 ? rest / 2 : rest;
    l.sourceBox = {col, top + status, width, source};
    if (rest - source >= 3) l.varsBox = {col, top + status + source, width, rest - source};
  } else {
    // Stacked: arena, status, a few source lines, output.
    int innerW = cols - 2;
    int source = rows >= 24 ? 5 : 0;
    int innerHMax = bottom - 1 - 2 - 3 - source - (1 + kOutputMinLines);
    int arenaRows = std::max(std::min(innerHMax, static_cast<int>(innerW / kColsPerRow)), 3);
    int arenaCols = std::min(innerW, static_cast<int>(std::lround(arenaRows * kColsPerRow)));
    l.arenaBox = {0, 1, arenaCols + 2, arenaRows + 2};
    l.arena = {1, 2, arenaCols, arenaRows};
    int below = l.arenaBox.row + l.arenaBox.height;
    l.status = {0, below, cols, 3};
    below += 3;
    if (source > 0) {
      l.sourceBox = {0, below, cols, source};
      below += source;
    }
    l.output = {0, below, cols, std::max(bottom - below, 0)};
  }
  auto inside = [](const Rect& box) {
    return box.width > 2 && box.height > 2 ? Rect{box.col + 1, box.row + 1, box.width - 2, box.height - 2}
                                           : Rect{};
  };
  l.source = inside(l.sourceBox);
  l.vars = inside(l.varsBox);
  return l;
}

std::pair<int, int> cellToPixel(const Rect& arena, int col, int row) {
  double x = (col - arena.col + 0.5) * Canvas::kWidth / arena.width;
  double y = (row - arena.row + 0.5) * Canvas::kHeight / arena.height;
  int px = std::clamp(static_cast<int>(std::floor(x)), 0, Canvas::kWidth - 1);
  int py = std::clamp(static_cast<int>(std::floor(y)), 0, Canvas::kHeight - 1);
  return {px, py};
}

std::pair<int, int> pixelToCell(const Rect& arena, int x, int y) {
  int c = static_cast<int>(std::floor(static_cast<double>(x) * arena.width / Canvas::kWidth));
  int r = static_cast<int>(std::floor(static_cast<double>(y) * arena.height / Canvas::kHeight));
  return {arena.col + c, arena.row + r};
}

namespace {
/// The first pixel of `cell` along an axis of `pixels` shown in `cells` cells: the smallest x
/// with floor(x * cells / pixels) >= cell.
int firstPixel(int cell, int cells, int pixels) {
  return static_cast<int>((static_cast<int64_t>(cell) * pixels + cells - 1) / cells);
}
}  // namespace

Rect cellPixels(const Rect& arena, int col, int row) {
  int c = std::clamp(col - arena.col, 0, std::max(arena.width - 1, 0));
  int r = std::clamp(row - arena.row, 0, std::max(arena.height - 1, 0));
  int x0 = firstPixel(c, arena.width, Canvas::kWidth), x1 = firstPixel(c + 1, arena.width, Canvas::kWidth);
  int y0 = firstPixel(r, arena.height, Canvas::kHeight),
      y1 = firstPixel(r + 1, arena.height, Canvas::kHeight);
  return {x0, y0, std::max(x1 - x0, 1), std::max(y1 - y0, 1)};
}

Rect cellsShowing(const Rect& arena, int x, int y, int w, int h) {
  int x0 = std::max(x, 0), y0 = std::max(y, 0);
  int x1 = std::min(x + w, Canvas::kWidth), y1 = std::min(y + h, Canvas::kHeight);
  if (arena.width <= 0 || arena.height <= 0 || x1 <= x0 || y1 <= y0) return {};
  auto [c0, r0] = pixelToCell(arena, x0, y0);
  auto [c1, r1] = pixelToCell(arena, x1 - 1, y1 - 1);
  return {c0, r0, c1 - c0 + 1, r1 - r0 + 1};
}

std::string bumperText(int bits) {
  static const int kValues[] = {1, 2, 4, 8};
  static const char* const kNames[] = {"rear", "right", "front", "left"};
  return bitsText(bits, kValues, kNames, 4);
}

std::string feelText(int bits) {
  static const int kValues[] = {1, 2, 4, 8, 16};
  static const char* const kNames[] = {"R", "FR", "F", "FL", "L"};
  return bitsText(bits, kValues, kNames, 5);
}

std::string speedText(double factor) {
  if (factor >= 1) return join({"x", std::to_string(std::lround(factor))});
  return join({"x1/", std::to_string(std::lround(1 / factor))});
}

namespace {
void fit(std::vector<std::string>& lines, int width) {
  for (std::string& line : lines)
    if (static_cast<int>(line.size()) > width) line.resize(static_cast<size_t>(std::max(width, 0)));
}
}  // namespace

std::vector<std::string> statusLines(const TuiStatus& s, int width) {
  std::vector<std::string> out;
  auto row = [&](const std::string& label, const std::string& value) {
    std::string line = label;
    line.resize(8, ' ');
    line += value;
    out.push_back(line);
  };
  row("state", s.state);
  std::string speed = speedText(s.speedFactor);
  if (s.rSpeed > 0) speed += join({"  rSpeed ", number(s.rSpeed)});
  row("speed", speed);
  if (s.located) {
    row("x", fixed1(s.x));
    row("y", fixed1(s.y));
    row("heading", fixed1(s.heading));
    row("pen", s.pen ? "down" : "up");
    row("bumper", s.sensors ? bumperText(s.bumper) : "-");
    row("feel", s.sensors ? feelText(s.feel) : "-");
    row("range", s.range ? number(*s.range) : "-");
  } else {
    row("robot", "not placed");
  }
  if (s.real) {
    row("link", s.port);
    row("sent", std::to_string(s.commands) + (s.commands == 1 ? " command" : " commands"));
    row("reply", s.lastReply.empty() ? "-" : s.lastReply);
  }
  fit(out, width);
  return out;
}

std::vector<std::string> compactStatusLines(const TuiStatus& s, int width) {
  std::vector<std::string> out;
  out.push_back(join({s.state, "  ", speedText(s.speedFactor)}));
  if (s.located) {
    out.push_back(join({"x ", fixed1(s.x), "  y ", fixed1(s.y), "  heading ", fixed1(s.heading),
                        "  pen ", s.pen ? "down" : "up"}));
    out.push_back(join({"bumper ", s.sensors ? bumperText(s.bumper) : "-", "  feel ",
                        s.sensors ? feelText(s.feel) : "-", "  range ",
                        s.range ? number(*s.range) : "-"}));
  } else {
    out.push_back("robot not placed");
  }
  if (s.real) out.push_back(join({"link ", s.port, "  sent ", std::to_string(s.commands)}));
  fit(out, width);
  return out;
}

std::string keysLine(int width, ViewState state, bool programKeys, bool watching) {
  struct Key {
    std::string text;
    bool always = false;  ///< shown whatever else is left out: how to quit
  };
  std::vector<Key> keys;
  switch (state) {
    case ViewState::Running:
    case ViewState::Paused:
      keys = {{state == ViewState::Paused ? "F2 run" : "F2 pause"}, {"F3 step"}};
      if (state == ViewState::Paused) keys.push_back({"Left back"});
      keys.insert(keys.end(), {{"F7 over"}, {"F8 pixel"}, {"F9 break"}, {"F11 watch"},
                               {"F12 restart"}, {"F4/F5 speed"}, {"F6 view"}, {"F10 quit", true}});
      if (state == ViewState::Paused) keys.push_back({"PgUp/PgDn variables"});
      if (!programKeys) keys.push_back({"(or p s n r b w g - + v q)"});
      break;
    case ViewState::Ended:
      // Nothing runs any more: pausing, stepping, breakpoints and the speed are gone.
      keys = {{"F12 restart"}, {"Left back"}, {"F11 watch"}, {"F6 view"}, {"F10 quit", true},
              {"PgUp/PgDn variables"}, {"any other key exits"}};
      break;
    case ViewState::BackPaused:
    case ViewState::BackEnded:
      // Looking back: the steps, and the way back to the present.
      keys = {{"Left/Right step"}, {"Home/End tenth"}, {"Esc now"}};
      if (state == ViewState::BackPaused) keys.insert(keys.end(), {{"F2 run"}, {"F3 step"}});
      keys.insert(keys.end(), {{"F9 break"}, {"F11 watch"}, {"F12 restart"}, {"F6 view"},
                               {"F10 quit", true}});
      break;
    case ViewState::NotLoaded:
      keys = {{"F12 load again"}, {"F10 quit", true}};
      break;
  }
  if (watching && (state == ViewState::Ended || state == ViewState::NotLoaded))
    keys.insert(keys.begin() + 1, {"(or save the file)"});
  // The most useful first, as many as fit; the keys that must show have their room kept.
  int room = width;
  for (const Key& k : keys)
    if (k.always) room -= static_cast<int>(k.text.size()) + 2;
  std::string line;
  for (const Key& k : keys) {
    int need = static_cast<int>(k.text.size()) + (line.empty() ? 0 : 2);
    if (!k.always) {
      if (need > room) continue;
      room -= need;
    } else if (static_cast<int>(line.size()) + need > width) {
      break;
    }
    if (!line.empty()) line += "  ";
    line += k.text;
  }
  return line;
}

}  // namespace rb::tui
