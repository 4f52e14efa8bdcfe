#include "curses_palette.h"

#include <catch2/catch.hpp>

using namespace rb::render;

TEST_CASE("terminal colours: the xterm cube and grey ramp", "[curses]") {
  CHECK(nearestXterm256(0x000000) == 16);
  CHECK(nearestXterm256(0xFFFFFF) == 231);
  CHECK(nearestXterm256(0xFF0000) == 196);
  CHECK(nearestXterm256(0x0000AA) == 19);   // VGA blue: (0, 0, 175)
  CHECK(nearestXterm256(0x808080) == 244);  // a grey lands on the ramp
}

TEST_CASE("terminal colours: the ANSI colours", "[curses]") {
  CHECK(nearestAnsi(0xFFFFFF, 8) == 7);
  CHECK(nearestAnsi(0xFFFFFF, 16) == 15);
  CHECK(nearestAnsi(0x0000AA, 8) == 4);
  CHECK(nearestAnsi(0xAA0000, 16) == 1);
  CHECK(nearestAnsi(0xAA5500, 8) == 3);  // VGA brown is the dark yellow
}
