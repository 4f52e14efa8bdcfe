// The live view's timeline: earlier steps from a recording, jumps, the position bar, the output
// as it was.
#include <catch2/catch.hpp>

#include "machine/test_support.h"
#include "tui_timeline.h"

using namespace rb;
using namespace rb::tui;

namespace {

/// A host that feeds a recording as the live view does.
class RecordingHost : public test::TestHost {
 public:
  explicit RecordingHost(Recording& r) : rec(r) {}
  void onLine(SourceLoc loc) override { rec.statement(loc, *machine); }
  void output(std::string_view text) override {
    TestHost::output(text);
    rec.output(text);
  }
  Recording& rec;
  Machine* machine = nullptr;
};

class Observer : public RobotObserver {
 public:
  explicit Observer(Recording& r) : rec(r) {}
  void robotEvent(const RobotEvent& e) override { rec.robotEvent(e); }
  Recording& rec;
};

std::string record(const std::string& text, Recording& rec) {
  test::MemoryReader reader;
  reader.files["test.bas"] = text;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  CompileOptions options;
  options.lineTracing = true;
  auto program = compileProgram(*loaded, options, diags);
  REQUIRE(program);
  RecordingHost host(rec);
  Machine machine(host, 1);
  host.machine = &machine;
  Observer observer(rec);
  machine.setObserver(&observer);
  Interpreter interp(*program, machine);
  RunResult r = interp.run({});
  rec.finish(machine, r);
  return host.out;
}

}  // namespace

TEST_CASE("timeline: an earlier step's screen, robot, line and output", "[tui][timeline]") {
  Recording rec(kTimelineBudget);
  std::string out = record(
      "rLocate 100, 200\n"         // 1
      "print \"one\"\n"            // 2
      "rectangle 0, 0, 10, 10, Red, Red\n"  // 3
      "rForward 30\n"              // 4
      "r = rRange()\n"             // 5
      "print \"two\"\n",           // 6
      rec);
  const std::vector<RecordedStep>& steps = rec.steps();
  REQUIRE(steps.size() == 7);  // six statements and the end
  // Before line 3 the screen has no red square; before line 4 it has.
  PastStep before = pastStep(rec, 2);
  CHECK(before.step.loc.line == 3);
  CHECK(before.screen[5 * Canvas::kWidth + 5] != colours::kRed);
  PastStep after = pastStep(rec, 3);
  CHECK(after.screen[5 * Canvas::kWidth + 5] == colours::kRed);
  CHECK(after.robot.visible);
  CHECK(after.robot.y == Approx(200));
  // After the move, the robot 30 pixels up; the range read on line 5 shows from then on.
  PastStep moved = pastStep(rec, 4);
  CHECK(moved.robot.y == Approx(170));
  CHECK_FALSE(moved.range);
  CHECK(pastStep(rec, 5).range);
  // The output so far: what was printed before each step.
  CHECK(out.substr(0, steps[2].output) == "one\n");
  CHECK(out.substr(0, steps[1].output).empty());
  CHECK(stepName(steps[0]) == "step 1");
  CHECK(stepName(steps.back()) == "the end");
}

TEST_CASE("timeline: jumps by a tenth of the run", "[tui][timeline]") {
  Recording rec(kTimelineBudget);
  record("for i = 1 to 500\n  x = i\nnext\n", rec);
  size_t last = rec.steps().size() - 1;
  uint64_t total = rec.steps().back().step;
  size_t back = jumpFrom(rec, last, -0.1);
  CHECK(rec.steps()[back].step == total - total / 10);
  CHECK(jumpFrom(rec, back, 0.1) == last);
  CHECK(jumpFrom(rec, 0, -0.1) == 0);
  CHECK(jumpFrom(rec, last, 0.1) == last);
  // A tiny fraction still moves one step.
  CHECK(jumpFrom(rec, 10, -0.0001) == 9);
  CHECK(jumpFrom(rec, 10, 0.0001) == 11);
}

TEST_CASE("timeline: the position bar and the steps its columns mean", "[tui][timeline]") {
  int col = 0, width = 0;
  std::string rule = timelineRule(40, "step 3 of 5", 2, 5, col, width);
  CHECK(rule.size() == 40);
  CHECK(rule.starts_with("-- step 3 of 5 ["));
  CHECK(col == 16);
  CHECK(width == 20);
  CHECK(rule.substr(16, 20) == "#########|..........");
  CHECK(rule.substr(36) == "] --");
  CHECK(stepAtColumn(col, col, width, 5) == 0);
  CHECK(stepAtColumn(col + width - 1, col, width, 5) == 4);
  CHECK(stepAtColumn(col + 9, col, width, 5) == 2);
  CHECK(stepAtColumn(0, col, width, 5) == 0);  // left of the bar: the start
  // The present is at the bar's end; no room, no bar.
  rule = timelineRule(40, "step 5 of 5", 4, 5, col, width);
  CHECK(rule.substr(16, 20) == "###################|");
  rule = timelineRule(20, "step 5 of 5", 4, 5, col, width);
  CHECK(width == 0);
  CHECK(rule == "-- step 5 of 5 -----");
  CHECK(grouped(1234567) == "1,234,567");
  CHECK(grouped(999) == "999");
}

TEST_CASE("timeline: the output as it was", "[tui][timeline]") {
  using V = std::vector<std::string_view>;
  CHECK(lastLines("", 3).empty());
  CHECK(lastLines("a\nb\nc\n", 2) == V{"b", "c"});
  CHECK(lastLines("a\nb\nc", 2) == V{"b", "c"});  // c not ended yet
  CHECK(lastLines("a\nb\n", 5) == V{"a", "b"});
  CHECK(lastLines("\n", 3) == V{""});
  CHECK(lastLines("a\n\nb", 3) == V{"a", "", "b"});
}
