// The live view's parts that need no terminal: stepping and breakpoints, held keys, the source
// and variables panes.
#include <catch2/catch.hpp>

#include "machine/test_support.h"
#include "tui_debugger.h"
#include "tui_keyboard.h"
#include "tui_panes.h"

using namespace rb;
using namespace rb::tui;

namespace {
SourceLoc at(uint32_t line, uint32_t col = 1, uint32_t file = 0) {
  SourceLoc l;
  l.file = file;
  l.line = line;
  l.col = col;
  return l;
}
}  // namespace

TEST_CASE("debugger: a statement step pauses at the next statement", "[tui]") {
  Debugger d;
  CHECK_FALSE(d.pauseAtStatement(at(1), 0));
  d.step(Debugger::Step::Into, 0);
  CHECK(d.pauseAtStatement(at(2), 1));  // into a gosub
  CHECK_FALSE(d.stoppedAtBreakpoint());
  CHECK(d.armed() == Debugger::Step::None);
  CHECK_FALSE(d.pauseAtStatement(at(3), 1));
}

TEST_CASE("debugger: stepping over a call pauses back at the caller's depth", "[tui]") {
  Debugger d;
  d.step(Debugger::Step::Over, 0);
  CHECK_FALSE(d.pauseAtStatement(at(10), 1));  // inside the gosub
  CHECK_FALSE(d.pauseAtStatement(at(11), 2));
  CHECK(d.pauseAtStatement(at(3), 0));  // returned
}

TEST_CASE("debugger: a robot step pauses after one pixel or at the next statement", "[tui]") {
  Debugger d;
  CHECK_FALSE(d.pauseAtRobotStep());
  d.step(Debugger::Step::Robot, 0);
  CHECK(d.pauseAtRobotStep());
  CHECK_FALSE(d.pauseAtRobotStep());
  d.step(Debugger::Step::Robot, 0);
  CHECK(d.pauseAtStatement(at(4), 0));
}

TEST_CASE("debugger: a breakpoint stops on arriving at its line", "[tui]") {
  Debugger d;
  d.addBreakpoint(0, 5);
  CHECK_FALSE(d.pauseAtStatement(at(4), 0));
  CHECK(d.pauseAtStatement(at(5, 1), 0));
  CHECK(d.stoppedAtBreakpoint());
  // Further statements of the same line do not stop again...
  CHECK_FALSE(d.pauseAtStatement(at(5, 10), 0));
  // ...but coming back to the line's start (a loop) does.
  CHECK(d.pauseAtStatement(at(5, 1), 0));
  // The same line of another file is another line.
  CHECK_FALSE(d.pauseAtStatement(at(5, 1, 1), 0));
  CHECK_FALSE(d.toggleBreakpoint(0, 5));
  CHECK_FALSE(d.hasBreakpoint(0, 5));
  CHECK(d.toggleBreakpoint(0, 6));
  CHECK(d.hasBreakpoint(0, 6));
}

TEST_CASE("held keys without releases: a tap is seen once", "[tui]") {
  using namespace std::chrono_literals;
  HeldKeys k;
  HeldKeys::Time t0{};
  k.press('a', t0 + 1s);
  CHECK(k.read(t0 + 1s + 1ms) == 'a');
  // A tap is not held for a while: the next read, a moment later, sees no key.
  CHECK(k.read(t0 + 1s + 30ms) == 0);
  // Auto-repeat (presses 40 ms apart) keeps it held between the repeats.
  k.press('b', t0 + 2s);
  CHECK(k.read(t0 + 2s + 1ms) == 'b');
  k.press('b', t0 + 2s + 40ms);
  CHECK(k.read(t0 + 2s + 60ms) == 'b');
  CHECK(k.read(t0 + 2s + 100ms) == 'b');
  CHECK(k.read(t0 + 2s + 40ms + HeldKeys::kRepeatHold + 1ms) == 0);
}

TEST_CASE("held keys with releases: held from press to release", "[tui]") {
  using namespace std::chrono_literals;
  HeldKeys k;
  k.setReportsReleases(true);
  HeldKeys::Time t0{};
  k.press('a', t0);
  CHECK(k.read(t0 + 1s) == 'a');
  CHECK(k.read(t0 + 2s) == 'a');
  k.release('a', t0 + 3s);
  CHECK(k.read(t0 + 3s) == 0);
  // A tap released before any read is still seen once.
  k.press('c', t0 + 4s);
  k.release('c', t0 + 4s + 10ms);
  CHECK(k.read(t0 + 5s) == 'c');
  CHECK(k.read(t0 + 5s + 1ms) == 0);
  // Releasing another key leaves the last one pressed held.
  k.press('d', t0 + 6s);
  k.release('e', t0 + 6s);
  CHECK(k.read(t0 + 7s) == 'd');
}

TEST_CASE("source pane: the running line highlighted, breakpoints marked", "[tui]") {
  std::string text;
  for (int i = 1; i <= 30; ++i) text += "x = " + std::to_string(i) + "\n";
  SourceFile f("a.bas", text);
  auto lines = sourceLines(f, 12, 9, 20, [](uint32_t n) { return n == 13; });
  REQUIRE(lines.size() == 9);
  // The running line a third of the way down.
  CHECK(lines[3].highlight);
  CHECK(lines[3].text == ">12 x = 12");
  CHECK(lines[4].marked);
  CHECK(lines[4].text == "*13 x = 13");
  CHECK(lines[0].text == "  9 x = 9");
  // Near the end the pane stays full.
  lines = sourceLines(f, 30, 9, 20, [](uint32_t) { return false; });
  CHECK(lines.back().text == ">30 x = 30");
  CHECK(lines.size() == 9);
  // After the end the pane stays where the run was, without the running line's marker.
  lines = sourceLines(f, 12, 9, 20, [](uint32_t n) { return n == 13; }, false);
  CHECK(lines[3].text == " 12 x = 12");
  CHECK_FALSE(lines[3].highlight);
  CHECK(lines[4].text == "*13 x = 13");
  // After an error, its line marked '!' (a breakpoint there too: the error's mark shows).
  lines = sourceLines(f, 13, 9, 20, [](uint32_t n) { return n == 13; }, false, 13);
  CHECK(lines[3].error);
  CHECK(lines[3].text == "!13 x = 13");
  CHECK_FALSE(lines[2].error);
  // Before the first statement: from the top; lines cut at the width, tabs expanded.
  SourceFile g("b.bas", "\tprint 1234567890\n");
  lines = sourceLines(g, 0, 5, 12, [](uint32_t) { return false; });
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].text == " 1     print");
}

TEST_CASE("variables pane: values, strings, arrays, locals", "[tui]") {
  Value n = Value::integer(42), s = Value::string("hi\tthere"), u;
  Value a = Value::array({3});
  a.arr().items[0] = Value::integer(7);
  Value local = Value::number(2.5);
  std::vector<VariableView> vars = {
      {"count", false, &n}, {"name", false, &s}, {"grid", false, &a}, {"unset", false, &u},
      {"r", true, &local}};
  auto lines = variableLines(vars, "area", 30);
  REQUIRE(lines.size() == 6);
  CHECK(lines[0] == "count 42");
  CHECK(lines[1] == "name  \"hi  there\"");
  CHECK(lines[2].starts_with("grid  [3] 7, "));
  CHECK(lines[3] == "unset -");
  CHECK(lines[4].starts_with("-- in sub area ---"));
  CHECK(lines[4].size() == 30);
  CHECK(lines[5] == "r     2.5");
  CHECK(valueText(Value::string(std::string(50, 'x')), 10) == "\"xxxxxx...");
}

TEST_CASE("output pane: tabs to 8-column stops, long lines wrapped", "[tui]") {
  // `print "with " ; n ; " sides"` writes a tab at each ';'.
  CHECK(outputCells("with \t8\t sides") == "with    8        sides");
  CHECK(outputCells("\tx") == "        x");
  CHECK(outputCells("1234567\tx") == "1234567 x");
  CHECK(outputCells("12345678\tx") == "12345678        x");
  CHECK(outputCells("bell\a") == "bell?");
  CHECK(wrapRows("", 10) == std::vector<std::string>{""});
  CHECK(wrapRows("abcdefghijkl", 5) == std::vector<std::string>{"abcde", "fghij", "kl"});
  CHECK(wrapRows("a\tb", 4) == std::vector<std::string>{"a   ", "    ", "b"});
  // A message wraps at its words; a word longer than a row is cut; nothing is lost.
  CHECK(wordRows("robot crashed into an obstacle", 12) ==
        std::vector<std::string>{"robot", "crashed into", "an obstacle"});
  CHECK(wordRows("see 'rInvisibleBlack' here", 8) ==
        std::vector<std::string>{"see", "'rInvisi", "bleBlack", "' here"});
  CHECK(wordRows("", 5) == std::vector<std::string>{""});
  CHECK(wordRows("fits", 4) == std::vector<std::string>{"fits"});
  // The last rows, wrapped lines counted as the rows they take.
  std::vector<std::string_view> lines = {"one", "two", "a long line that wraps", "end"};
  CHECK(lastRows(lines, 10, 4) ==
        std::vector<std::string>{"a long lin", "e that wra", "ps", "end"});
  CHECK(lastRows(lines, 80, 10) == std::vector<std::string>{"one", "two", "a long line that wraps", "end"});
  CHECK(lastRows(lines, 10, 0).empty());
}

namespace {
std::unique_ptr<Program> traced(const std::string& text) {
  test::MemoryReader reader;
  reader.files["test.bas"] = text;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  CompileOptions options;
  options.lineTracing = true;
  return compileProgram(*loaded, options, diags);
}
}  // namespace

TEST_CASE("statement lines: where a run can stop", "[tui]") {
  auto program = traced(
      "// a comment\n"     // 1
      "x = 1\n"            // 2
      "\n"                 // 3
      "if x = 1\n"         // 4
      "  print 1\n"        // 5
      "else\n"             // 6
      "  print 2\n"        // 7
      "endif\n"            // 8
      "for i = 1 to 2\n"   // 9
      "next\n"             // 10
      "Done:\n"            // 11
      "end\n"              // 12
      "sub Foo()\n"        // 13
      "  print 3\n"        // 14
      "endsub\n"           // 15
      "// the end\n");     // 16
  REQUIRE(program);
  StatementLines lines(*program);
  for (uint32_t n : {2u, 4u, 5u, 6u, 7u, 8u, 9u, 10u, 12u, 14u}) CHECK(lines.has(0, n));
  for (uint32_t n : {1u, 3u, 11u, 13u, 15u, 16u}) CHECK_FALSE(lines.has(0, n));
  CHECK(lines.atOrAfter(0, 1) == 2);
  CHECK(lines.atOrAfter(0, 11) == 12);
  CHECK(lines.atOrAfter(0, 13) == 14);
  CHECK(lines.atOrAfter(0, 15) == 0);
  CHECK(lines.atOrAfter(1, 1) == 0);  // no such file

  BreakpointPlace same = placeBreakpoint(lines, 0, 5);
  CHECK(same.line == 5);
  CHECK_FALSE(same.moved);
  CHECK(same.note.empty());
  BreakpointPlace moved = placeBreakpoint(lines, 0, 3);
  CHECK(moved.line == 4);
  CHECK(moved.moved);
  CHECK(moved.note == "line 3 holds no statement: the breakpoint is on line 4, the next that does");
  BreakpointPlace refused = placeBreakpoint(lines, 0, 16);
  CHECK(refused.line == 0);
  CHECK(refused.note == "no statement on or after line 16: nothing there can stop the run");
}

TEST_CASE("variables pane: watches with their values or errors", "[tui]") {
  CHECK(watchLines({}, 30).empty());
  auto lines = watchLines({{"x * 2", "14", false},
                           {"a[9] + 1", "index 9 is out of range for 'a' (valid: 0 to 3)", true},
                           {"s", "\"" + std::string(40, 'y') + "\"", false}},
                          24);
  REQUIRE(lines.size() == 6);
  CHECK(lines[0] == "-- watch ---------------");
  CHECK(lines[1] == "x * 2 = 14");
  CHECK(lines[2] == "a[9] + 1: index 9 is out");
  CHECK(lines[3] == "   of range for 'a' (val");
  CHECK(lines[4] == "  id: 0 to 3)");
  CHECK(lines[5] == "s = \"yyyyyyyyyyyyyyyy...");
}
