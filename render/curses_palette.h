#pragma once
// Colours for the terminal view: the nearest colour a terminal can show for an 0xRRGGBB one.
// Pure functions (no curses), so they are tested without a terminal.

#include <cstdint>

namespace rb::render {

/// The xterm 256-colour index (16..255: the 6x6x6 cube and the grey ramp) nearest to `rgb`.
int nearestXterm256(uint32_t rgb);

/// The nearest ANSI colour in curses numbering: 0 black, 1 red, 2 green, 3 yellow, 4 blue,
/// 5 magenta, 6 cyan, 7 white, 8..15 their bright forms. With `count` 8 a bright colour is
/// given as its base colour (bright yellow as 3).
int nearestAnsi(uint32_t rgb, int count);

}  // namespace rb::render
