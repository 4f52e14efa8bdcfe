#pragma once
// The arena as a grid of terminal characters: a pure function from the screen's pixels and the
// robot to cells, used by `rb render --ascii` and by the live terminal view (rb run --tui), and
// golden-tested without a terminal.

#include <cstdint>
#include <string>
#include <vector>

#include "screen/canvas.h"

namespace rb::render {

enum class CellMode {
  Ascii,      ///< one character per cell, chosen by how much of the cell is drawn on
  HalfBlock,  ///< two pixels-rows per cell with the half-block characters (UTF-8)
  Braille,    ///< 2 x 4 dots per cell with the braille characters (UTF-8)
};

struct Cell {
  std::string glyph = " ";   ///< one character, UTF-8
  uint32_t fg = 0x000000;    ///< 0xRRGGBB
  uint32_t bg = 0xFFFFFF;    ///< 0xRRGGBB
};

struct ArenaFrame {
  int cols = 0, rows = 0;
  std::vector<Cell> cells;   ///< row-major, rows * cols
  Cell& at(int col, int row) { return cells[static_cast<size_t>(row) * cols + col]; }
  const Cell& at(int col, int row) const { return cells[static_cast<size_t>(row) * cols + col]; }
};

/// The robot as the view draws it (never part of the screen's pixels).
struct RobotView {
  bool visible = false;
  double x = 0, y = 0, heading = 0, radius = 20;
  Colour colour = 1;
};

struct ArenaOptions {
  int cols = 100, rows = 37;
  CellMode mode = CellMode::Ascii;
  /// The canvas's display list, when text the program drew should show as characters: each
  /// character whose cell is readable at this scale (its advance and height at least
  /// kReadableCells of a cell) and still shows in the pixels (some pixel of its box has its
  /// colour) becomes that character in its colour; the rest stays pixels. Text drawn before
  /// the last clearScr or scroll is left alone (its place is not known any more).
  const std::vector<DrawOp>* textOps = nullptr;
};

/// How much of a cell a character must cover, across and down, to be shown as a character.
constexpr double kReadableCells = 0.75;

/// Scales the 800 x 600 screen (`pixels`, row-major colour numbers) into cols x rows cells with
/// the robot's image (its 3-pixel ring and heading line, robot_image.h) drawn in, and puts a
/// glyph showing its heading in the cell of its centre.
ArenaFrame renderArena(const Pixels& pixels, Colour background, const RobotView& robot,
                       const ArenaOptions& options);

/// The frame's characters as text: one line per row, each ending in "\n".
std::string frameText(const ArenaFrame& frame);

}  // namespace rb::render
