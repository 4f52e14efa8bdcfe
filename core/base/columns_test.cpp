#include "base/columns.h"

#include <catch2/catch.hpp>

using rb::displayColumn;
using rb::utf16Column;

TEST_CASE("columns: UTF-16 code units", "[base]") {
  // s = "😀é" + foo(x): foo starts at byte 16, UTF-16 unit 13, and ends before unit 16.
  std::string line = "s = \"\xF0\x9F\x98\x80\xC3\xA9\" + foo(x)";
  CHECK(utf16Column(line, 1) == 1);
  CHECK(utf16Column(line, 6) == 6);    // the emoji
  CHECK(utf16Column(line, 10) == 8);   // é after a surrogate pair
  CHECK(utf16Column(line, 16) == 13);  // foo
  CHECK(utf16Column(line, 19) == 16);  // after foo
  CHECK(utf16Column(line, 8) == 8);    // inside the emoji: counted as before it
  CHECK(utf16Column("ab", 5) == 5);    // past the end: a unit a byte
}

TEST_CASE("columns: display columns as gcc counts them", "[base]") {
  CHECK(displayColumn("\tfoo", 2) == 9);
  CHECK(displayColumn("ab\tfoo", 4) == 9);
  CHECK(displayColumn("\xE4\xB8\xAD\xE6\x96\x87 x", 8) == 6);  // two CJK characters, a space
  CHECK(displayColumn("e\xCC\x81x", 4) == 2);                  // e + a combining accent
  CHECK(displayColumn("\xF0\x9F\x98\x80x", 5) == 3);           // an emoji is two wide
  CHECK(rb::codePointWidth(U'a') == 1);
  CHECK(rb::codePointWidth(0x4E2D) == 2);
  CHECK(rb::codePointWidth(0x0301) == 0);
  CHECK(rb::codePointWidth(0xAC00) == 2);
}
