#include "tui_layout.h"

#include <catch2/catch.hpp>

using namespace rb::tui;

TEST_CASE("tui layout: the arena beside the status panel", "[tui]") {
  TuiLayout l = layoutTui(100, 30);
  REQUIRE_FALSE(l.tooSmall);
  CHECK(l.title.row == 0);
  CHECK(l.arena.col == 1);
  CHECK(l.arena.row == 2);
  // About 4:3 on cells twice as tall as wide; the panel takes two fifths.
  CHECK(l.arena.width == 56);
  CHECK(l.arena.height == 21);
  CHECK(l.status.col == l.arenaBox.width + 1);
  CHECK(l.status.col + l.status.width == 100);
  CHECK(l.output.row == l.arenaBox.row + l.arenaBox.height);
  CHECK(l.output.row + l.output.height == l.keys.row);
  CHECK(l.keys.row == 29);
  CHECK(l.output.height >= 4);
}

TEST_CASE("tui layout: wide terminals are limited by their height", "[tui]") {
  TuiLayout l = layoutTui(240, 50);
  CHECK(l.arena.height == 50 - 1 - 2 - 4 - 1);
  CHECK(l.arena.width == 112);
}

TEST_CASE("tui layout: narrow terminals put the status under the arena", "[tui]") {
  TuiLayout l = layoutTui(60, 30);
  REQUIRE_FALSE(l.tooSmall);
  CHECK(l.status.col == 0);
  CHECK(l.status.row == l.arenaBox.row + l.arenaBox.height);
  CHECK(l.status.height == 3);
  CHECK(l.arena.width <= 58);
  // A few source lines between the status and the output; no variables pane.
  CHECK(l.sourceBox.row == l.status.row + l.status.height);
  CHECK(l.sourceBox.height == 5);
  CHECK(l.varsBox.height == 0);
  CHECK(l.output.row == l.sourceBox.row + l.sourceBox.height);
  CHECK(layoutTui(39, 30).tooSmall);
  CHECK(layoutTui(80, 11).tooSmall);
}

TEST_CASE("tui layout: cells and pixels", "[tui]") {
  Rect arena{1, 2, 80, 30};
  CHECK(cellToPixel(arena, 1, 2) == std::pair{5, 10});
  CHECK(cellToPixel(arena, 80, 31) == std::pair{795, 590});
  // Outside the arena: clamped to the screen.
  CHECK(cellToPixel(arena, 0, 0) == std::pair{0, 0});
  CHECK(cellToPixel(arena, 200, 100) == std::pair{799, 599});
  CHECK(pixelToCell(arena, 0, 0) == std::pair{1, 2});
  CHECK(pixelToCell(arena, 799, 599) == std::pair{80, 31});
  for (int c = 1; c <= 80; c += 7)
    for (int r = 2; r <= 31; r += 5) {
      auto [x, y] = cellToPixel(arena, c, r);
      CHECK(pixelToCell(arena, x, y) == std::pair{c, r});
    }
}

TEST_CASE("tui status panel", "[tui]") {
  TuiStatus s;
  s.state = "paused";
  s.speedFactor = 0.25;
  s.rSpeed = 5;
  s.located = true;
  s.x = 400;
  s.y = 180.25;
  s.heading = -0.01;
  s.pen = true;
  s.bumper = 6;
  s.feel = 12;
  s.range = 37;
  auto lines = statusLines(s, 26);
  auto has = [&](const std::string& text) {
    for (const auto& l : lines)
      if (l == text) return true;
    return false;
  };
  CHECK(has("state   paused"));
  CHECK(has("speed   x1/4  rSpeed 5"));
  CHECK(has("y       180.2"));
  CHECK(has("heading 0.0"));
  CHECK(has("pen     down"));
  CHECK(has("bumper  6 right+front"));
  CHECK(has("feel    12 F+FL"));
  CHECK(has("range   37"));
  CHECK_FALSE(has("link    /dev/ttyUSB0"));
  for (const auto& l : lines) CHECK(l.size() <= 26);
  s.located = false;
  s.real = true;
  s.port = "/dev/ttyUSB0";
  s.commands = 12;
  s.lastReply = "cmd 3,90 -> 04 00 00 = 0";
  lines = statusLines(s, 40);
  CHECK(has("robot   not placed"));
  CHECK(has("link    /dev/ttyUSB0"));
  CHECK(has("sent    12 commands"));
  CHECK(has("reply   cmd 3,90 -> 04 00 00 = 0"));
  auto compact = compactStatusLines(s, 200);
  CHECK(compact[0] == "paused  x1/4");
  CHECK(compact[1] == "robot not placed");
  CHECK(compact[2] == "link /dev/ttyUSB0  sent 12");
  CHECK(speedText(8) == "x8");
  CHECK(bumperText(0) == "0");
}

TEST_CASE("tui keys line: the most useful keys that fit", "[tui]") {
  using V = ViewState;
  CHECK(keysLine(200, V::Running, false).starts_with("F2 pause  F3 step  F7 over"));
  CHECK(keysLine(200, V::Running, false).ends_with("F6 view  F10 quit  (or p s n r b w g - + v q)"));
  CHECK(keysLine(200, V::Running, false).find("F11 watch  F12 restart") != std::string::npos);
  CHECK(keysLine(200, V::Paused, true).find("F2 run") == 0);
  CHECK(keysLine(200, V::Paused, true).find("(or") == std::string::npos);
  CHECK(keysLine(200, V::Paused, true).find("PgUp/PgDn") != std::string::npos);
  // How to quit always shows; the rest as room allows, in order.
  CHECK(keysLine(27, V::Running, false) == "F2 pause  F3 step  F10 quit");
  CHECK(keysLine(100, V::Running, true).ends_with("F10 quit"));
  CHECK(keysLine(100, V::Running, true).size() <= 100);
  CHECK(keysLine(8, V::Running, false) == "F10 quit");
  CHECK(keysLine(3, V::Running, false).empty());
  // After the end only what can still be done: no pause, step, breakpoint or speed.
  std::string ended = keysLine(200, V::Ended, false);
  CHECK(ended.find("F6 view") != std::string::npos);
  CHECK(ended.find("F10 quit") != std::string::npos);
  for (const char* gone : {"F2", "F3", "F7", "F8", "F9", "F4", "(or"})
    CHECK(ended.find(gone) == std::string::npos);
  CHECK(ended.starts_with("F12 restart"));
  CHECK(keysLine(200, V::Ended, false, true).starts_with("F12 restart  (or save the file)"));
  // A program that does not load: load it again, or quit.
  CHECK(keysLine(200, V::NotLoaded, false) == "F12 load again  F10 quit");
}

TEST_CASE("tui layout: source and variables panes beside the arena", "[tui]") {
  TuiLayout l = layoutTui(160, 50);
  REQUIRE(l.sourceBox.height > 0);
  REQUIRE(l.varsBox.height > 0);
  CHECK(l.sourceBox.col == l.status.col);
  CHECK(l.sourceBox.row == l.status.row + l.status.height);
  CHECK(l.varsBox.row == l.sourceBox.row + l.sourceBox.height);
  CHECK(l.varsBox.row + l.varsBox.height == l.keys.row);
  CHECK(l.source.width == l.sourceBox.width - 2);
  CHECK(l.keys.row == 49);
  // 80 x 24: a source box still fits beside the arena.
  TuiLayout small = layoutTui(80, 24);
  CHECK(small.sourceBox.height > 0);
  CHECK(small.keys.row == 23);
}

TEST_CASE("tui: the pixels of a cell and the cells of an area agree", "[tui]") {
  Rect arena{1, 2, 61, 23};
  // Every pixel maps to a cell whose pixel area holds it.
  for (int x = 0; x < 800; x += 7) {
    for (int y = 0; y < 600; y += 11) {
      auto [c, r] = pixelToCell(arena, x, y);
      Rect p = cellPixels(arena, c, r);
      CHECK(x >= p.col);
      CHECK(x < p.col + p.width);
      CHECK(y >= p.row);
      CHECK(y < p.row + p.height);
    }
  }
  // Neighbouring cells tile the screen without gaps or overlaps.
  Rect a = cellPixels(arena, 10, 5), b = cellPixels(arena, 11, 5);
  CHECK(a.col + a.width == b.col);
  // A button of 48 x 24 pixels at (700, 20) shows on the cells its pixels fall in.
  Rect cells = cellsShowing(arena, 700, 20, 48, 24);
  CHECK(cells.col == 1 + 700 * 61 / 800);
  CHECK(cells.col + cells.width - 1 == 1 + 747 * 61 / 800);
  CHECK(cells.height >= 1);
  // Off the screen: no cells.
  CHECK(cellsShowing(arena, 900, 20, 10, 10).width == 0);
}
