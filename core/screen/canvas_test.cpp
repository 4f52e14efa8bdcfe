#include <catch2/catch.hpp>

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
  c.print(std::string(150, 'x'), true);
  CHECK(c.textCursor() == Point{0, 32});
}
