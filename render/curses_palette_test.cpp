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

TEST_CASE("terminal colours: RobotBASIC's palette lands on the matching terminal colours", "[curses]") {
  CHECK(nearestXterm256(0xFF0000) == 196);  // Red
  CHECK(nearestXterm256(0x0000FF) == 21);   // Blue
  CHECK(nearestXterm256(0x008080) == 30);   // Cyan (0, 128, 128): cube (0, 135, 135)
  CHECK(nearestXterm256(0xC0C0C0) == 250);  // Gray on the grey ramp (188)
  CHECK(nearestAnsi(0xFF0000, 16) == 1);    // Red: ANSI red (#AA0000) is nearer than bright red
  CHECK(nearestAnsi(0x0000FF, 8) == 4);     // Blue
  CHECK(nearestAnsi(0x008080, 8) == 6);     // Cyan
  CHECK(nearestAnsi(0xC0C0C0, 16) == 7);    // Gray: the ANSI "white" (light grey)
  CHECK(nearestAnsi(0xFF8080, 16) == 9);    // LightRed
  // On 8 colours the light colours keep their hue (they are nearest their bright twins).
  CHECK(nearestAnsi(0xFFFF00, 8) == 3);     // Yellow
  CHECK(nearestAnsi(0x8080FF, 8) == 4);     // LightBlue
  CHECK(nearestAnsi(0x80FF80, 8) == 2);     // LightGreen
  CHECK(nearestAnsi(0xFF8080, 8) == 1);     // LightRed
  CHECK(nearestAnsi(0xFFFFFF, 8) == 7);     // White
}
