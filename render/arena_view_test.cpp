// The character view of the arena: golden frames of small programs in every cell mode, thin
// lines staying visible, dominant colours, the robot's glyph, and speed.

#include <catch2/catch.hpp>

#include <map>

#include "arena_view.h"
#include "render_test_support.h"

namespace rb::render {
namespace {

using test::runForPicture;

const char* modeName(CellMode m) {
  switch (m) {
    case CellMode::Ascii: return "ascii";
    case CellMode::HalfBlock: return "half";
    case CellMode::Braille: return "braille";
  }
  return "?";
}

/// A frame as reviewable text: the glyphs, then a grid of foreground colours (one letter per
/// non-blank cell), then a grid of background colours where they differ from the screen's
/// background (half blocks), then the letters' colours. Golden files hold this, so a change of
/// colour fails a test as surely as a change of glyph.
std::string describeFrame(const ArenaFrame& frame, uint32_t backgroundRgb) {
  std::map<uint32_t, char> letters;
  std::string legend;
  auto letter = [&](uint32_t rgb) {
    auto it = letters.find(rgb);
    if (it != letters.end()) return it->second;
    char l = static_cast<char>('a' + letters.size());
    letters[rgb] = l;
    char line[32];
    std::snprintf(line, sizeof line, "%c #%06x\n", l, static_cast<unsigned>(rgb));
    legend += line;
    return l;
  };
  std::string fg, bg;
  bool anyBg = false;
  for (int row = 0; row < frame.rows; ++row) {
    for (int col = 0; col < frame.cols; ++col) {
      const Cell& c = frame.at(col, row);
      fg += c.glyph == " " ? ' ' : letter(c.fg);
      if (c.bg != backgroundRgb) {
        anyBg = true;
        bg += letter(c.bg);
      } else {
        bg += ' ';
      }
    }
    fg += '\n';
    bg += '\n';
  }
  std::string out = frameText(frame) + "-- foreground\n" + fg;
  if (anyBg) out += "-- background\n" + bg;
  return out + "-- colours\n" + legend;
}

struct GoldenProgram {
  const char* name;
  std::string text;
};

std::vector<GoldenProgram> goldenPrograms() {
  return {
      {"rectangle", "rectangle 100, 100, 700, 500\nlineWidth 3\nrectangle 200, 200, 400, 300, RED, YELLOW\n"},
      {"circle", "circle 250, 150, 550, 450, BLUE\ncircle 40, 40, 160, 160, RED, LIGHTGREEN\n"
                 "line 0, 599, 799, 0, 1, MAGENTA\n"},
      {"fig_1_7", test::readText(test::sourceRoot() / "examples" / "fig_1_7.bas")},
      {"text", "print \"print: line one\"\nprint \"line two\"\n"
               "xyText 100, 200, \"Hello, rb!\", \"Courier\", 24, \"b\", RED\n"
               "xyText 100, 400, \"framed\", \"Courier\", 12, \"u\", BLUE, YELLOW\n"},
  };
}

TEST_CASE("renderArena: golden frames of small programs in every mode", "[render][arena]") {
  for (const GoldenProgram& prog : goldenPrograms()) {
    REQUIRE_FALSE(prog.text.empty());
    auto run = runForPicture(prog.text);
    INFO(prog.name << ": " << run->diagnostics);
    REQUIRE(run->loaded);
    REQUIRE(run->result.status == RunStatus::Finished);
    for (CellMode mode : {CellMode::Ascii, CellMode::HalfBlock, CellMode::Braille}) {
      ArenaOptions opts;
      opts.mode = mode;
      const Canvas& canvas = run->canvas();
      ArenaFrame frame = renderArena(canvas.pixels(), canvas.background(), run->robot(), opts);
      std::string name = std::string(prog.name) + "_" + modeName(mode) + ".txt";
      test::GoldenResult g = test::checkGolden(name, describeFrame(frame, colourToRgb(canvas.background())));
      if (g.updated) WARN("updated testdata/render/" << name);
      INFO(g.message);
      CHECK(g.matched);
    }
  }
}

TEST_CASE("renderArena: a frame has rows * cols cells and frameText one line per row", "[render][arena]") {
  Pixels screen(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight, colours::kWhite);
  ArenaOptions opts;
  opts.cols = 7;
  opts.rows = 3;
  ArenaFrame f = renderArena(screen, colours::kWhite, RobotView{}, opts);
  REQUIRE(f.cells.size() == 21);
  CHECK(frameText(f) == "       \n       \n       \n");
  CHECK(f.at(6, 2).bg == 0xFFFFFF);
}

TEST_CASE("renderArena: a one-pixel line never vanishes in ASCII mode", "[render][arena]") {
  // At 100 x 37 a cell is 8 x 16 or 17 pixels: a one-pixel line covers a sixteenth of it.
  auto run = runForPicture("line 0, 5, 799, 5\nline 3, 0, 3, 599\nline 0, 0, 799, 599\n");
  REQUIRE(run->loaded);
  ArenaOptions opts;
  ArenaFrame f = renderArena(run->canvas().pixels(), run->canvas().background(), RobotView{}, opts);
  for (int col = 0; col < opts.cols; ++col) CHECK(f.at(col, 0).glyph != " ");
  for (int row = 0; row < opts.rows; ++row) CHECK(f.at(0, row).glyph != " ");
  // The diagonal crosses every row; in each row some cell shows it.
  for (int row = 1; row < opts.rows; ++row) {
    int drawn = 0;
    for (int col = 1; col < opts.cols; ++col) drawn += f.at(col, row).glyph != " ";
    CHECK(drawn > 0);
  }
  // And in a coarse grid too, where a cell is 80 x 60 pixels.
  opts.cols = 10;
  opts.rows = 10;
  f = renderArena(run->canvas().pixels(), run->canvas().background(), RobotView{}, opts);
  for (int i = 0; i < 10; ++i) CHECK(f.at(i, i).glyph != " ");
}

TEST_CASE("renderArena: density chooses the ASCII glyph", "[render][arena]") {
  auto run = runForPicture("rectangle 0, 0, 799, 599, BLACK, BLACK\n");
  REQUIRE(run->loaded);
  ArenaFrame f = renderArena(run->canvas().pixels(), colours::kWhite, RobotView{}, ArenaOptions{});
  CHECK(f.at(50, 20).glyph == "#");
  CHECK(f.at(50, 20).fg == 0x000000);
  CHECK(f.at(50, 20).bg == 0xFFFFFF);
  // The same screen seen with black as the background is empty.
  f = renderArena(run->canvas().pixels(), colours::kBlack, RobotView{}, ArenaOptions{});
  CHECK(f.at(50, 20).glyph == " ");
  CHECK(f.at(50, 20).bg == 0x000000);
}

TEST_CASE("renderArena: the foreground is the block's dominant colour", "[render][arena]") {
  Pixels screen(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight, colours::kWhite);
  // The top-left cell of a 100 x 37 grid is 8 x 16 pixels: 40 red pixels, 8 blue ones.
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 8; ++x) screen[static_cast<size_t>(y) * Canvas::kWidth + x] = colours::kRed;
  for (int x = 0; x < 8; ++x) screen[static_cast<size_t>(10) * Canvas::kWidth + x] = colours::kBlue;
  ArenaFrame f = renderArena(screen, colours::kWhite, RobotView{}, ArenaOptions{});
  CHECK(f.at(0, 0).fg == 0xFF0000);

  SECTION("half blocks: the top and the bottom keep their own colours") {
    ArenaOptions opts;
    opts.mode = CellMode::HalfBlock;
    f = renderArena(screen, colours::kWhite, RobotView{}, opts);
    // The upper half (rows 0..7) is red, the lower (8..15) blue: two colours in one cell.
    CHECK(f.at(0, 0).glyph == "\u2580");
    CHECK(f.at(0, 0).fg == 0xFF0000);
    CHECK(f.at(0, 0).bg == 0x0000FF);
  }
  SECTION("braille: dots where drawn, coloured by the whole cell's dominant colour") {
    ArenaOptions opts;
    opts.mode = CellMode::Braille;
    f = renderArena(screen, colours::kWhite, RobotView{}, opts);
    // Dot rows are 4 pixels: 0..3 and 4..7 hold red (dots 1, 4, 2, 5), 8..11 blue (3, 6),
    // 12..15 nothing (7, 8).
    CHECK(f.at(0, 0).glyph == "\u283F");
    CHECK(f.at(0, 0).fg == 0xFF0000);
  }
}

TEST_CASE("renderArena: half blocks show upper, lower and full cells", "[render][arena]") {
  Pixels screen(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight, colours::kWhite);
  auto fill = [&](int x0, int y0, int x1, int y1, Colour c) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) screen[static_cast<size_t>(y) * Canvas::kWidth + x] = c;
  };
  fill(0, 0, 8, 8, colours::kGreen);     // cell (0, 0): upper half only
  fill(8, 8, 16, 16, colours::kGreen);   // cell (1, 0): lower half only
  fill(16, 0, 24, 16, colours::kGreen);  // cell (2, 0): both, one colour
  ArenaOptions opts;
  opts.mode = CellMode::HalfBlock;
  ArenaFrame f = renderArena(screen, colours::kWhite, RobotView{}, opts);
  CHECK(f.at(0, 0).glyph == "\u2580");
  CHECK(f.at(1, 0).glyph == "\u2584");
  CHECK(f.at(2, 0).glyph == "\u2588");
  CHECK(f.at(3, 0).glyph == " ");
  for (int col = 0; col < 3; ++col) {
    CHECK(f.at(col, 0).fg == 0x008000);
    CHECK(f.at(col, 0).bg == 0xFFFFFF);
  }
}

TEST_CASE("renderArena: the robot is one glyph showing its heading", "[render][arena]") {
  Pixels screen(static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight, colours::kWhite);
  RobotView robot;
  robot.visible = true;
  robot.x = 400;
  robot.y = 300;
  robot.colour = colours::kRed;
  const char* ascii[8] = {"^", "/", ">", "\\", "v", "/", "<", "\\"};
  const char* arrows[8] = {"\u2191", "\u2197", "\u2192", "\u2198", "\u2193", "\u2199", "\u2190", "\u2196"};
  ArenaOptions asciiOpts, halfOpts, brailleOpts;
  halfOpts.mode = CellMode::HalfBlock;
  brailleOpts.mode = CellMode::Braille;
  for (int i = 0; i < 8; ++i) {
    // Slightly off the sector's centre, and once more a full turn later: both round the same.
    for (double heading : {i * 45.0 + 10, i * 45.0 - 10 + 360}) {
      robot.heading = heading;
      INFO("heading " << heading);
      ArenaFrame f = renderArena(screen, colours::kWhite, robot, asciiOpts);
      // 400 / 8 = column 50; row 300 * 37 / 600 = 18.5: row 18.
      CHECK(f.at(50, 18).glyph == ascii[i]);
      CHECK(f.at(50, 18).fg == 0xFF0000);
      CHECK(renderArena(screen, colours::kWhite, robot, halfOpts).at(50, 18).glyph == arrows[i]);
      CHECK(renderArena(screen, colours::kWhite, robot, brailleOpts).at(50, 18).glyph == arrows[i]);
    }
  }
  SECTION("a robot that is not placed, or off the screen, draws nothing") {
    robot.visible = false;
    CHECK(frameText(renderArena(screen, colours::kWhite, robot, asciiOpts)).find_first_not_of(" \n") ==
          std::string::npos);
    robot.visible = true;
    robot.x = -30;
    CHECK(frameText(renderArena(screen, colours::kWhite, robot, asciiOpts)).find_first_not_of(" \n") ==
          std::string::npos);
  }
  SECTION("the glyph sits in the cell holding the robot's centre pixel at the grid's edges") {
    robot.heading = 0;
    robot.x = 799;
    robot.y = 599;
    ArenaFrame f = renderArena(screen, colours::kWhite, robot, asciiOpts);
    CHECK(f.at(99, 36).glyph == "^");
    robot.x = 0;
    robot.y = 0;
    f = renderArena(screen, colours::kWhite, robot, asciiOpts);
    CHECK(f.at(0, 0).glyph == "^");
  }
}

TEST_CASE("renderArena: any grid size works, even finer than the screen", "[render][arena]") {
  auto run = runForPicture("line 0, 300, 799, 300\n");
  REQUIRE(run->loaded);
  for (auto [cols, rows] : {std::pair{1, 1}, std::pair{3, 7}, std::pair{1000, 700}}) {
    for (CellMode mode : {CellMode::Ascii, CellMode::HalfBlock, CellMode::Braille}) {
      ArenaOptions opts;
      opts.cols = cols;
      opts.rows = rows;
      opts.mode = mode;
      ArenaFrame f = renderArena(run->canvas().pixels(), run->canvas().background(), RobotView{}, opts);
      INFO(cols << " x " << rows << " " << modeName(mode));
      REQUIRE(f.cells.size() == static_cast<size_t>(cols) * rows);
      CHECK(frameText(f).find_first_not_of(" \n") != std::string::npos);
    }
  }
}

// The time a frame takes is a benchmark's business, not a test's: a timed check failed on a
// busy machine under the sanitizers.
TEST_CASE("renderArena: the same screen gives the same frame every time", "[render][arena]") {
  auto run = runForPicture(test::readText(test::sourceRoot() / "examples" / "fig_1_7.bas") +
                           "circle 100, 100, 300, 300, RED, YELLOW\nxyString 10, 500, \"text\"\n");
  REQUIRE(run->loaded);
  const Canvas& canvas = run->canvas();
  for (CellMode mode : {CellMode::Ascii, CellMode::HalfBlock, CellMode::Braille}) {
    ArenaOptions opts;
    opts.mode = mode;
    const std::string first = frameText(renderArena(canvas.pixels(), canvas.background(), run->robot(), opts));
    INFO(modeName(mode));
    for (int i = 0; i < 5; ++i)
      CHECK(frameText(renderArena(canvas.pixels(), canvas.background(), run->robot(), opts)) == first);
  }
}

TEST_CASE("renderArena: drawn text shows as characters where its cells are readable", "[render][arena]") {
  auto run = runForPicture(
      "xyText 40, 200, \"HELLO\", \"Courier New\", 48, 0, BLACK, WHITE\n"
      "xyText 40, 400, \"tiny\", \"Courier New\", 8, 0, BLACK, WHITE\n");
  REQUIRE(run->loaded);
  ArenaOptions opts;
  opts.cols = 56;
  opts.rows = 21;
  opts.textOps = &run->canvas().displayList();
  ArenaFrame f = renderArena(run->machine->shownScreen(), run->canvas().background(), run->robot(), opts);
  std::string text = frameText(f);
  // Each letter in its cell, the cells around it blank: the word reads on one row.
  std::string joined;
  for (char c : text)
    if (c != ' ') joined += c;
  CHECK(joined.find("HELLO\n") != std::string::npos);
  CHECK(text.find("tiny") == std::string::npos);  // too small: it stays pixels
  // Without the display list the text is pixels only.
  opts.textOps = nullptr;
  std::string pixelsOnly = frameText(renderArena(run->machine->shownScreen(), run->canvas().background(),
                                                 run->robot(), opts));
  CHECK(pixelsOnly.find("H") == std::string::npos);
}

}  // namespace
}  // namespace rb::render
