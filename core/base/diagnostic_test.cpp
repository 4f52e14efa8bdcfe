#include <catch2/catch.hpp>

#include "base/diagnostic.h"

using namespace rb;

TEST_CASE("diagnostics print file:line:col, the line in a gutter and the word underlined", "[diagnostic]") {
  SourceSet s;
  s.add("prog.bas", "x = 1\n  prit \"a\"\n");
  Diagnostic d{Severity::Error, {0, 2, 3}, "unknown command 'prit'; did you mean 'print'?",
               "rb-unknown-command"};
  d.fixits.push_back({{0, 2, 3}, {0, 2, 7}, "print"});
  CHECK(formatDiagnostic(s, d) ==
        "prog.bas:2:3: error: unknown command 'prit'; did you mean 'print'? [rb-unknown-command]\n"
        "    2 |   prit \"a\"\n"
        "      |   ^~~~\n"
        "      |   print\n");
}

TEST_CASE("an insertion is shown at its column, without the spaces after it", "[diagnostic]") {
  SourceSet s;
  s.add("p.bas", "x = \"a\"n\n");
  Diagnostic d{Severity::Error, {0, 1, 8}, "missing '+' between \"a\" and 'n'", "rb-missing-operator"};
  d.fixits.push_back({{0, 1, 8}, {0, 1, 8}, " + "});
  CHECK(formatDiagnostic(s, d) ==
        "p.bas:1:8: error: missing '+' between \"a\" and 'n' [rb-missing-operator]\n"
        "    1 | x = \"a\"n\n"
        "      |        ^\n"
        "      |         +\n");
}

TEST_CASE("a range is underlined from its start to its end", "[diagnostic]") {
  SourceSet s;
  s.add("p.bas", "x = abs(1, 2 + 3)\n");
  Diagnostic d{Severity::Error, {0, 1, 12}, "too many", "rb-argument-count", {0, 1, 16}};
  CHECK(formatDiagnostic(s, d) ==
        "p.bas:1:12: error: too many [rb-argument-count]\n"
        "    1 | x = abs(1, 2 + 3)\n"
        "      |            ^~~~~\n");
  d.loc.col = 5;  // a string literal is one word
  d.end = {};
  s.add("q.bas", "x = \"a b\" + 1\n");
  d.loc.file = 1;
  CHECK(formatDiagnostic(s, d).find("      |     ^~~~~\n") != std::string::npos);
}

TEST_CASE("the caret keeps tabs so it lines up", "[diagnostic]") {
  SourceSet s;
  s.add("p.bas", "\tx = y\n");
  Diagnostic d{Severity::Warning, {0, 1, 6}, "w"};
  CHECK(formatDiagnostic(s, d) == "p.bas:1:6: warning: w\n    1 | \tx = y\n      | \t    ^\n");
}

TEST_CASE("colour marks the location, the severity and the range", "[diagnostic]") {
  SourceSet s;
  s.add("p.bas", "goto nowhere\n");
  Diagnostic d{Severity::Error, {0, 1, 6}, "undefined label 'nowhere'", "rb-undefined-label"};
  CHECK(formatDiagnostic(s, d, DiagnosticStyle{true}) ==
        "\033[1mp.bas:1:6:\033[m \033[1;31merror:\033[m undefined label 'nowhere' "
        "[\033[1;31mrb-undefined-label\033[m]\n"
        "    1 | goto nowhere\n"
        "      |      \033[1;32m^~~~~~~\033[m\n");
}

TEST_CASE("a diagnostic in an included file names the include chain", "[diagnostic]") {
  SourceSet s;
  s.add("main.bas", "#include \"a.bas\"\n");
  s.add("a.bas", "#include \"b.bas\"\n", {0, 1, 1});
  s.add("b.bas", "oops\n", {1, 1, 1});
  Diagnostic d{Severity::Error, {2, 1, 1}, "unknown command 'oops'"};
  CHECK(formatDiagnostic(s, d) ==
        "In file included from a.bas:1,\n"
        "                 from main.bas:1:\n"
        "b.bas:1:1: error: unknown command 'oops'\n"
        "    1 | oops\n"
        "      | ^~~~\n");
}

TEST_CASE("notes attached to a diagnostic follow it; a note without a line names no file", "[diagnostic]") {
  SourceSet s;
  s.add("p.bas", "gosub Work\nend\nWork:\nx = 1 / 0\n");
  Diagnostic d{Severity::Error, {0, 4, 5}, "division by zero", "rb-runtime", {0, 4, 9}};
  d.notes.push_back({Severity::Note, {0, 1, 1}, "called from here"});
  d.notes.push_back({Severity::Note, {}, "usage: x"});
  CHECK(formatDiagnostic(s, d) ==
        "p.bas:4:5: error: division by zero [rb-runtime]\n"
        "    4 | x = 1 / 0\n"
        "      |     ^~~~~\n"
        "p.bas:1:1: note: called from here\n"
        "    1 | gosub Work\n"
        "      | ^~~~~\n"
        "note: usage: x\n");
}

TEST_CASE("a file-level error names the file without a line", "[diagnostic]") {
  SourceSet s;
  s.add("ls", "");
  Diagnostic d{Severity::Error, {0, 0, 0}, "this is a binary file, not a program", "rb-binary-input"};
  CHECK(formatDiagnostic(s, d) == "ls: error: this is a binary file, not a program [rb-binary-input]\n");
}

TEST_CASE("program text: BOM skipped, Windows-1252 converted, binary detected", "[diagnostic][source]") {
  DecodedText a = decodeSourceText("\xEF\xBB\xBFprint 1\n");
  CHECK(a.kind == DecodedText::Utf8);
  CHECK(a.hadBom);
  CHECK(a.text == "print 1\n");
  DecodedText b = decodeSourceText("print \"caf\xE9 \x80\"\n");
  CHECK(b.kind == DecodedText::Windows1252);
  CHECK(b.text == "print \"caf\xC3\xA9 \xE2\x82\xAC\"\n");
  DecodedText c = decodeSourceText(std::string("\x7f" "ELF\x02\x01\x01\0\0", 9));
  CHECK(c.kind == DecodedText::Binary);
  CHECK(c.why == "a NUL byte at byte 8");
  DecodedText u = decodeSourceText("print \"caf\xC3\xA9\"\n");
  CHECK(u.kind == DecodedText::Utf8);
  CHECK(u.text == "print \"caf\xC3\xA9\"\n");
  DecodedText ctl = decodeSourceText("\x01\x02\x03\x04 abc");
  CHECK(ctl.kind == DecodedText::Binary);
}

TEST_CASE("the first error of a line can be found again, also after sorting", "[diagnostic]") {
  DiagnosticList diags;
  diags.warning({0, 3, 1}, "a warning");
  diags.error({0, 4, 1}, "first on line 4");
  diags.error({0, 4, 9}, "second on line 4");
  diags.error({0, 2, 5}, "on line 2");
  REQUIRE(diags.firstErrorAt({0, 4, 1}));
  diags.firstErrorAt({0, 4, 1})->message += " (more)";
  CHECK(diags.all()[1].message == "first on line 4 (more)");
  CHECK(diags.firstErrorAt({0, 4, 9}) == nullptr);  // not the first of its line
  CHECK(diags.firstErrorAt({0, 3, 1}) == nullptr);  // a warning
  CHECK(diags.firstErrorAt({1, 4, 1}) == nullptr);  // another file
  diags.sort();
  REQUIRE(diags.firstErrorAt({0, 2, 5}));
  CHECK(diags.firstErrorAt({0, 2, 5})->message == "on line 2");
  CHECK(diags.firstErrorAt({0, 4, 1})->message == "first on line 4 (more)");
  CHECK(diags.hasErrorOnLine(0, 4));
  CHECK_FALSE(diags.hasErrorOnLine(0, 3));
}
