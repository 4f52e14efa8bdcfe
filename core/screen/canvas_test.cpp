#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "screen/canvas.h"

using namespace rb;

TEST_CASE("a print that scrolls a whole screen draws only what stays visible, identically",
          "[canvas]") {
  // The same text printed line by line (scrolling each time) and in one huge print (which
  // skips the lines that scroll away) must leave the same pixels and cursor.
  std::string lines;
  for (int i = 0; i < 120; ++i) {
    std::string line = "line " + std::to_string(i) + "\tcol\t" + std::string(static_cast<size_t>(i % 130), 'x');
    lines += line + "\n";
  }
  Canvas slow, fast;
  slow.rectangle({100, 100}, {300, 300}, 1, colours::kRed, colours::kRed);
  fast.rectangle({100, 100}, {300, 300}, 1, colours::kRed, colours::kRed);
  slow.print("start ", false);
  fast.print("start ", false);
  size_t pos = 0;
  while (pos < lines.size()) {
    size_t end = lines.find('\n', pos);
    slow.print(lines.substr(pos, end - pos), true);
    pos = end + 1;
  }
  fast.print(lines.substr(0, lines.size() - 1), true);
  CHECK(fast.textCursor() == slow.textCursor());
  CHECK(fast.pixels() == slow.pixels());
}

TEST_CASE("print wraps at the right edge and expands tabs to 8 columns", "[canvas]") {
  Canvas c;
  c.print("ab\tc", false);
  CHECK(c.textCursor() == Point{9 * 8, 0});
  // 100 columns of 8 pixels: 150 characters take two lines of 15 pixels.
  c.print(std::string(150, 'x'), true);
  CHECK(c.textCursor() == Point{0, 30});
}

TEST_CASE("the palette: RobotBASIC 4.2's colours, light twins lifted by 128", "[canvas]") {
  using namespace colours;
  // Confirmed by screenshots of RobotBASIC 4.2.
  CHECK(colourToRgb(kRed) == 0xFF0000);
  CHECK(colourToRgb(kBlue) == 0x0000FF);
  CHECK(colourToRgb(kCyan) == 0x008080);
  CHECK(colourToRgb(kGray) == 0xC0C0C0);
  CHECK(colourToRgb(kLightRed) == 0xFF8080);
  // Chosen: every light colour is its dark twin (number - 8) with 128 added to each channel.
  for (Colour dark : {kBlack, kBlue, kGreen, kCyan, kRed, kMagenta, kGray}) {
    uint32_t d = colourToRgb(dark), l = colourToRgb(dark + 8);
    for (int shift : {0, 8, 16}) {
      uint32_t dc = (d >> shift) & 0xFF, lc = (l >> shift) & 0xFF;
      INFO("colour " << dark << " channel " << shift);
      CHECK(lc == std::min<uint32_t>(dc + 128, 255));
    }
  }
  CHECK(colourToRgb(kGreen) == 0x008000);
  CHECK(colourToRgb(kBrown) == 0x804000);
  CHECK(colourToRgb(kYellow) == 0xFFFF00);
  CHECK(colourToRgb(kWhite) == 0xFFFFFF);
  // RGB() numbers above 15 are r + 256 g + 65536 b.
  CHECK(colourToRgb(rgbColour(18, 52, 86)) == 0x123456);
}
