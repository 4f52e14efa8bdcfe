#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "base/diagnostic.h"
#include "base/source.h"
#include "lang/ast.h"
#include "lang/builtins.h"
#include "lang/lexer.h"
#include "lang/parser.h"
#include "lang/suggest.h"

using namespace rb;

namespace {
using K = BuiltinKind;

/// A few rows shaped like the standard table's: the suggestions read names, kinds, parameter
/// names, groups and help texts.
const BuiltinTable& table() {
  static const BuiltinTable t({
      {"rForward", K::Command, "robot", "distance", nullptr, 0, "moves the robot forward"},
      {"rPen", K::Command, "robot", "state", nullptr, 0, "Down (or non-zero) draws the robot's path, Up (0) stops"},
      {"setColor", K::Command, "graphics", "colour [, background]", nullptr, 0, "drawing colour"},
      {"rLocate", K::Command, "robot", "x, y [, heading]", nullptr, 0, "places the robot, heading 0 = up"},
      {"delay", K::Command, "time", "ms", nullptr, 0, "waits ms milliseconds"},
      {"length", K::Function, "string", "s", nullptr, 0, "number of characters"},
      {"abs", K::Function, "math", "x", nullptr, 0, "absolute value"},
      {"Up", K::Constant, "constant", "", nullptr, 0, "pen up (0)"},
      {"Down", K::Constant, "constant", "", nullptr, 1, "pen down (1)"},
      {"On", K::Constant, "constant", "", nullptr, 1, "1"},
      {"Red", K::Constant, "colour", "", nullptr, 4, "colour 4"},
      {"Green", K::Constant, "colour", "", nullptr, 2, "colour 2"},
      {"Brown", K::Constant, "colour", "", nullptr, 6, "colour 6"},
  });
  return t;
}

std::vector<std::string_view> fitting(std::string_view builtin, std::string_view param) {
  return constantsFitting(table(), *table().find(builtin, K::Command), param);
}
}  // namespace

TEST_CASE("edit distance counts inserts, deletes, substitutions and swaps", "[suggest]") {
  CHECK(editDistance("next", "next", false) == 0);
  CHECK(editDistance("nxt", "next", false) == 1);
  CHECK(editDistance("prnit", "print", false) == 1);  // neighbours swapped
  CHECK(editDistance("Print", "print", false) == 1);
  CHECK(editDistance("Print", "print", true) == 0);
  CHECK(editDistance("abcdef", "uvwxyz", false, 2) == 3);  // past the bound: bound + 1
}

TEST_CASE("the closest candidate wins, a tie going to one with the word's first letter", "[suggest]") {
  std::vector<std::string_view> names = {"end", "wend", "not", "next"};
  CHECK(closestMatch("wnd", names, true) == "wend");  // end and wend are both one edit away
  CHECK(closestMatch("nxt", names, true) == "not");   // not and next tie, both begin with n
  CHECK(closestMatch("NEXT", names, true) == "next");  // the same apart from case
  CHECK(closestMatch("zz", names, true).empty());    // two letters: too short to guess
  CHECK(closestMatch("qqqq", names, true).empty());
}

TEST_CASE("a statement's first word is matched against commands and statement keywords only", "[suggest]") {
  // `not` is an operator and `to` belongs inside a for: neither starts a statement.
  const std::vector<std::string_view>& words = statementKeywords();
  auto has = [&](std::string_view w) { return std::find(words.begin(), words.end(), w) != words.end(); };
  CHECK(has("next"));
  CHECK(has("print"));
  CHECK(has("endif"));
  CHECK(has("rem"));
  CHECK_FALSE(has("not"));
  CHECK_FALSE(has("and"));
  CHECK_FALSE(has("mod"));
  CHECK_FALSE(has("then"));
  CHECK_FALSE(has("to"));
  CHECK_FALSE(has("step"));

  CHECK(suggestCommand(table(), "nxt") == "next");
  CHECK(suggestCommand(table(), "wnd") == "wend");
  CHECK(suggestCommand(table(), "endf") == "endif");
  CHECK(suggestCommand(table(), "prit") == "print");
  CHECK(suggestCommand(table(), "rForwrd") == "rForward");
  CHECK(suggestCommand(table(), "lenght").empty());  // a function cannot start a statement
  CHECK(suggestCommand(table(), "nto").empty());     // nor can `not`
}

TEST_CASE("the constants that fit an argument come from the parameter and the help", "[suggest]") {
  // rPen's help names Down and Up; `up` in rLocate's help is an ordinary word.
  CHECK(fitting("rPen", "state") == std::vector<std::string_view>{"Up", "Down"});
  CHECK(fitting("rLocate", "heading").empty());
  // A colour parameter takes the colours.
  CHECK(fitting("setColor", "colour") == std::vector<std::string_view>{"Red", "Green", "Brown"});
  CHECK(fitting("setColor", "background") == std::vector<std::string_view>{"Red", "Green", "Brown"});
  CHECK(fitting("rForward", "distance").empty());
}

TEST_CASE("a value read but never assigned suggests a fitting constant, a variable, a constant", "[suggest]") {
  std::vector<std::string_view> variables = {"count", "Brwn", "total"};
  std::vector<std::string_view> pen = fitting("rPen", "state");
  CHECK(suggestValue("dwn", pen, variables, table()) == "Down");
  CHECK(suggestValue("Dwn", {}, variables, table()) == "Down");  // any constant, when none fits
  CHECK(suggestValue("cuont", pen, variables, table()) == "count");
  CHECK(suggestValue("Total", {}, variables, table()) == "total");
  // A tie between a variable and a constant: the constant that fits the argument first, else
  // the program's own variable.
  std::vector<std::string_view> colours = fitting("setColor", "colour");
  CHECK(suggestValue("Brwon", colours, variables, table()) == "Brown");
  CHECK(suggestValue("Brwon", {}, variables, table()) == "Brwn");
  CHECK(suggestValue("zzzzz", pen, variables, table()).empty());
}

TEST_CASE("a free name is no built-in's, no keyword and no name of the program", "[suggest]") {
  SourceSet sources;
  uint32_t f = sources.add("main.bas",
                           "length = 100\nMyLength = 1 // myAbs in a comment is no name\nabs1 = 2\n"
                           "sub Side(width)\n  myDelay[1] = width\nendsub\ngoto Far\n");
  DiagnosticList diags;
  ast::Arena arena;
  std::unordered_set<std::string> names;
  for (const ast::Stmt* s : parseTokens(lex(sources, f, diags), arena, table(), diags)) addNamesOf(*s, names);
  REQUIRE_FALSE(diags.hasErrors());
  CHECK(names == std::unordered_set<std::string>{"length", "mylength", "abs1", "side", "width", "mydelay", "far"});

  CHECK(freeName("length", table(), names) == "length1");  // myLength is taken, in any case
  CHECK(freeName("LENGTH", table(), {}) == "myLength");    // the built-in's spelling
  CHECK(freeName("abs", table(), names) == "myAbs");        // a comment holds no names
  CHECK(freeName("abs", table(), {"myabs", "abs1"}) == "abs2");
  CHECK(freeName("delay", table(), names) == "delay1");
  CHECK(freeName("Red", table(), {}) == "myRed");
}
