#include <catch2/catch.hpp>

#include "lang/lexer.h"

using namespace rb;

namespace {
std::vector<Token> tokens(const std::string& text, DiagnosticList& diags) {
  static SourceSet sources;  // tokens refer into the text, which must outlive them
  uint32_t f = sources.add("t.bas", text);
  return lex(sources, f, diags);
}
std::vector<Tok> kinds(const std::string& text) {
  DiagnosticList d;
  std::vector<Tok> out;
  for (const Token& t : tokens(text, d)) out.push_back(t.kind);
  return out;
}
}  // namespace

TEST_CASE("keywords ignore case, names keep it", "[lexer]") {
  DiagnosticList d;
  auto t = tokens("PRINT Print x X", d);
  CHECK(t[0].kind == Tok::KwPrint);
  CHECK(t[1].kind == Tok::KwPrint);
  CHECK(t[2].kind == Tok::Ident);
  CHECK(t[2].text == "x");
  CHECK(t[3].text == "X");
}

TEST_CASE("comments of every form are dropped", "[lexer]") {
  CHECK(kinds("x // c") == std::vector<Tok>{Tok::Ident, Tok::Newline, Tok::Eof});
  CHECK(kinds("x ' c") == std::vector<Tok>{Tok::Ident, Tok::Newline, Tok::Eof});
  CHECK(kinds("rem c\nx") == std::vector<Tok>{Tok::Newline, Tok::Ident, Tok::Newline, Tok::Eof});
  CHECK(kinds("x /* a\nb */ y") ==
        std::vector<Tok>{Tok::Ident, Tok::Newline, Tok::Ident, Tok::Newline, Tok::Eof});
}

TEST_CASE("strings keep comment markers and backslashes", "[lexer]") {
  DiagnosticList d;
  auto t = tokens("\"a // b ' c \\n\"", d);
  REQUIRE(t[0].kind == Tok::String);
  CHECK(t[0].text == "a // b ' c \\n");
  CHECK_FALSE(d.hasErrors());
}

TEST_CASE("numbers: integers, doubles, hex, exponents", "[lexer]") {
  DiagnosticList d;
  auto t = tokens("42 3.5 .25 1e3 0x1F 99999999999999999999", d);
  CHECK(t[0].kind == Tok::Int);
  CHECK(t[0].intValue == 42);
  CHECK(t[1].kind == Tok::Float);
  CHECK(t[1].floatValue == 3.5);
  CHECK(t[2].floatValue == 0.25);
  CHECK(t[3].kind == Tok::Float);
  CHECK(t[3].floatValue == 1000);
  CHECK(t[4].intValue == 31);
  CHECK(t[5].kind == Tok::Float);
}

TEST_CASE("operators, BASIC and C style", "[lexer]") {
  CHECK(kinds("<> != == <= >= << >> && || ++ -- += -= *= /=") ==
        std::vector<Tok>{Tok::NotEq, Tok::NotEq, Tok::EqEq, Tok::LessEq, Tok::GreaterEq, Tok::Shl,
                         Tok::Shr, Tok::AndAnd, Tok::OrOr, Tok::PlusPlus, Tok::MinusMinus,
                         Tok::PlusAssign, Tok::MinusAssign, Tok::StarAssign, Tok::SlashAssign,
                         Tok::Newline, Tok::Eof});
}

TEST_CASE("positions are 1-based line and column, CRLF included", "[lexer]") {
  DiagnosticList d;
  auto t = tokens("a\r\n  bb", d);
  CHECK(t[0].loc.line == 1);
  CHECK(t[0].loc.col == 1);
  CHECK(t[2].loc.line == 2);
  CHECK(t[2].loc.col == 3);
}

TEST_CASE("lexical errors are reported and skipped", "[lexer]") {
  DiagnosticList d;
  auto t = tokens("x @ y", d);
  REQUIRE(d.errorCount() == 1);
  CHECK(d.all()[0].message == "unexpected character '@'");
  CHECK(t[1].text == "y");
}
