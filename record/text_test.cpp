#include "text.h"

#include <catch2/catch.hpp>

using rb::record::toUtf8;

TEST_CASE("text becomes UTF-8 without losing Latin-1 bytes", "[grade][text]") {
  CHECK(toUtf8("plain") == "plain");
  CHECK(toUtf8("caf\xC3\xA9") == "caf\xC3\xA9");                // UTF-8 stays
  CHECK(toUtf8("caf\xE9") == "caf\xC3\xA9");                    // Latin-1 é becomes UTF-8 é
  CHECK(toUtf8("\xE2\x82") == "\xC3\xA2\xC2\x82");              // a cut sequence: byte by byte
  CHECK(toUtf8("\xC0\x80") == "\xC3\x80\xC2\x80");              // an overlong encoding is not UTF-8
  CHECK(toUtf8("\xED\xA0\x80") == "\xC3\xAD\xC2\xA0\xC2\x80");  // nor is a surrogate
  CHECK(toUtf8("a\x01z") == "a\x01z");
  CHECK(toUtf8("a\x01z", true) == "a\xEF\xBF\xBDz");            // XML cannot carry ^A
  CHECK(toUtf8("tab\tnl\n", true) == "tab\tnl\n");
}

using rb::record::csvTextField;
using rb::record::shownText;
using rb::record::TextShape;

namespace {
std::string line(std::string_view s) { return shownText(s, TextShape::Line); }
std::string block(std::string_view s) { return shownText(s, TextShape::Block); }
}  // namespace

TEST_CASE("untrusted text shows its control characters", "[grade][text]") {
  CHECK(line("plain caf\xC3\xA9") == "plain caf\xC3\xA9");
  CHECK(line("caf\xE9") == "caf\xC3\xA9");  // Latin-1 é, as toUtf8 reads it
  // ESC [2J (clear the screen), a cursor move, OSC 52 (set the clipboard) ended by BEL.
  CHECK(line("\x1b[2J\x1b[1;1Hpass\x1b]52;c;ZXZpbA==\x07") == "^[[2J^[[1;1Hpass^[]52;c;ZXZpbA==^G");
  CHECK(line(std::string_view("a\0b", 3)) == "a^@b");
  CHECK(line("\x7f\x1f\x01") == "^?^_^A");
  // C1 controls: CSI as UTF-8 (U+009B), as a lone byte, NEL.
  CHECK(line("\xC2\x9B" "2J") == "\\x9b2J");
  CHECK(line("\x9b" "2J") == "\\x9b2J");
  CHECK(line("\xC2\x85" "x\x80") == "\\x85x\\x80");
  CHECK(line("\xC2\xA0") == "\xC2\xA0");  // U+00A0 is no control
  // Bidirectional overrides reorder what is shown; separators break lines in a browser.
  CHECK(line("a\xE2\x80\xAE" "b\xE2\x80\xA8" "c") == "a\\u202eb\\u2028c");
}

TEST_CASE("untrusted text as one line or as lines", "[grade][text]") {
  CHECK(line("a\nb\r\nc\td") == "a\\nb\\r\\nc\\td");
  CHECK(block("a\nb\r\nc\td\n") == "a\nb^M\nc\td\n");
  CHECK(block("progress 10%\rprogress 20%") == "progress 10%^Mprogress 20%");
}

TEST_CASE("untrusted text starts no GitHub workflow command", "[grade][text]") {
  CHECK(line("::error::forged") == "\\x3a:error::forged");
  CHECK(block("  \t::add-mask::x") == "  \t\\x3a:add-mask::x");  // the runner trims blanks first
  CHECK(line("\t::add-mask::x") == "\\t::add-mask::x");            // as one line, the tab is shown
  CHECK(line("\xC2\xA0\xE3\x80\x80::stop-commands::t") == "\xC2\xA0\xE3\x80\x80\\x3a:stop-commands::t");
  CHECK(line("a::error::b") == "a::error::b");  // not at the start of a line: nothing to do
  CHECK(line("x\n::error::y") == "x\\n::error::y");  // one line: the LF is two characters
  CHECK(block("ok\n    ::error file=a.bas::forged\n") == "ok\n    \\x3a:error file=a.bas::forged\n");
  CHECK(block(":\n::") == ":\n\\x3a:");
  // The runner's older form is found anywhere in a line.
  CHECK(line("see ##[error]forged") == "see \\x23#[error]forged");
  CHECK(line("###[x") == "#\\x23#[x");
  CHECK(line("# heading [1]") == "# heading [1]");
  for (const char* s : {"::error::x", "###[y", "\x1b[2J\r\n::a::b", "caf\xE9\x9b"}) {
    CHECK(line(line(s)) == line(s));
    CHECK(block(block(s)) == block(s));
  }
}

TEST_CASE("a CSV text field starts no formula", "[grade][text]") {
  CHECK(csvTextField("=HYPERLINK(\"http://x\",\"y\").bas") == "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\").bas\"");
  CHECK(csvTextField("@SUM(1).bas") == "'@SUM(1).bas");
  CHECK(csvTextField("+1") == "'+1");
  CHECK(csvTextField("-2 points") == "'-2 points");
  CHECK(csvTextField("\tx") == "\\tx");  // a tab is shown, so the field no longer starts with one
  CHECK(csvTextField("a=b") == "a=b");
  CHECK(csvTextField("ann, bo") == "\"ann, bo\"");
  CHECK(csvTextField("a\nb") == "a\\nb");
}
