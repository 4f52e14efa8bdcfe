#include "checks.h"

#include <catch2/catch.hpp>
#include <limits>

using namespace rb::grade;
using rb::record::DiagRecord;
using rb::record::P2;
using rb::record::Polylines;
using rb::record::Region;
using rb::record::RunRecord;
using rb::record::Screen;
using rb::record::imageOf;
using rb::record::printedOutput;
using rb::record::screenOf;

namespace {

RunOutcome finished(Polylines trail, P2 end, std::string output = "") {
  RunOutcome run;
  run.seed = 1;
  run.process.kind = JobOutcome::Exited;
  run.output = std::move(output);
  RunRecord r;
  r.status = "finished";
  r.steps = 17;
  r.statements = 9;
  r.moves = 9;
  r.located = true;
  r.pos = end;
  r.path = trail;
  r.trail = std::move(trail);
  run.record = r;
  return run;
}

Check check(Check::Kind kind, double tolerance = 0) {
  Check c;
  c.kind = kind;
  c.name = kindName(kind);
  c.tolerance = tolerance;
  return c;
}

const Polylines kSquare{{{400, 300}, {400, 180}, {520, 180}, {520, 300}, {400, 300}}};
const Polylines kThree{{{400, 300}, {400, 180}, {520, 180}, {520, 300}}};

}  // namespace

TEST_CASE("output differences name the line", "[grade][checks]") {
  CHECK(outputDifference("a\nb\n", "a\nb\n", false).empty());
  CHECK(outputDifference("a\nb\n", "a\nc\n", false) == "output differs at line 2: expected \"b\", got \"c\"");
  CHECK(outputDifference("a\nb\n", "a\n", false) == "output ends after 1 line; expected 2, the next being \"b\"");
  CHECK(outputDifference("", "x\n", false) == "output has 1 line, expected 0; line 1 is \"x\"");
  CHECK(outputDifference("a\n", "a", false) == "output lacks the newline at its end");
  CHECK(outputDifference("a\n", "a", true).empty());  // by line: the last newline does not count
  CHECK(outputDifference("tab\there\n", "tab here\n", false) ==
        "output differs at line 1: expected \"tab\\there\", got \"tab here\"");
}

TEST_CASE("assignment checks pass and fail by how much", "[grade][checks]") {
  Assignment a;
  References refs;
  refs.solution.push_back(finished(kSquare, {400, 300}, "perimeter 480\n"));

  Check ends = check(Check::EndsIn);
  Region circle;
  circle.kind = Region::Circle;
  circle.cx = 400;
  circle.cy = 300;
  circle.r = 5;
  ends.regions = {circle};
  Check corners = check(Check::Visits, 3);
  corners.name = "corners";
  corners.targets = {{400, 300}, {400, 180}, {520, 180}, {520, 300}, {400, 300}};
  Check trail = check(Check::Trail, 3);
  trail.reference = kSquare;
  Check output = check(Check::Output);
  output.text = "perimeter 480";
  a.checks = {check(Check::NoError), check(Check::SolutionOutput), corners, check(Check::SolutionTrail, 3), ends,
              trail, output};

  SECTION("the solution's twin passes everything") {
    std::vector<CheckResult> r = checkAssignment(a, refs, {finished(kSquare, {400, 300}, "perimeter 480\n")}).checks;
    for (const CheckResult& c : r) CHECK(c.passed);
    for (const CheckResult& c : r) CHECK(c.earned == c.points);
    CHECK(r[3].message == "the trail is within 0 px of the solution's, 3 px allowed");
  }
  SECTION("three sides") {
    std::vector<CheckResult> r = checkAssignment(a, refs, {finished(kThree, {520, 300}, "perimeter 480\n")}).checks;
    CHECK(r[0].passed);
    CHECK(r[1].passed);
    CHECK_FALSE(r[2].passed);
    CHECK(r[2].earned == 0);
    CHECK(r[2].name == "corners");
    CHECK(r[2].message ==
          "the robot misses point 5 (400, 300) after point 4 by 117 px: it comes within 120 px, 3 px allowed");
    CHECK_FALSE(r[3].passed);
    CHECK(r[3].message.rfind("the trail is 60 px off the solution's at its worst, 3 px allowed: the solution's passes (460, 300), 60 px from the trail", 0) == 0);
    CHECK(r[4].message == "the robot ends at (520, 300), 115 px outside the circle of radius 5 around (400, 300)");
    CHECK(r[5].message.rfind("the trail is 60 px off the reference at its worst, 3 px allowed", 0) == 0);
    CHECK(r[6].passed);
  }
  SECTION("a run that stopped with a runtime error") {
    RunOutcome crash = finished({{{400, 300}, {400, 20}}}, {400, 20});
    crash.record->status = "error";
    crash.record->crashed = true;
    crash.record->steps = 5;
    crash.record->error = DiagRecord{"crashing.bas", 6, 1, "error", "robot crashed into an obstacle"};
    std::vector<CheckResult> r = checkAssignment(a, refs, {crash}).checks;
    CHECK(r[0].message == "the robot crashed at crashing.bas:6:1 after 5 steps: robot crashed into an obstacle");
    CHECK(r[1].message ==
          "output ends after 0 lines; expected 1, the next being \"perimeter 480\" (the solution's output)");
  }
  SECTION("a run that could not happen fails every check with the reason") {
    RunOutcome killed;
    killed.process.kind = JobOutcome::TimedOut;
    killed.processText = "killed after 10 s (the time limit)";
    for (const CheckResult& c : checkAssignment(a, refs, {killed}).checks) {
      CHECK_FALSE(c.passed);
      CHECK(c.message == "killed after 10 s (the time limit)");
    }
  }
  SECTION("several seeds: the first failing one is named") {
    refs.solution.push_back(refs.solution[0]);
    RunOutcome second = finished(kSquare, {420, 300}, "perimeter 480\n");
    second.seed = 2;
    std::vector<CheckResult> r = checkAssignment(a, refs, {finished(kSquare, {400, 300}, "perimeter 480\n"), second}).checks;
    CHECK(r[1].passed);
    CHECK_FALSE(r[4].passed);
    CHECK(r[4].message.rfind("seed 2: the robot ends at (420, 300), 15 px outside", 0) == 0);
  }
}

TEST_CASE("comment expectations: golden-test semantics", "[grade][checks]") {
  CommentSpec spec;
  spec.output = {"12"};
  RunOutcome run = finished({}, {0, 0}, "12\n");
  run.record->located = false;
  auto failures = [](const std::vector<CheckResult>& r) {
    std::vector<std::string> out;
    for (const CheckResult& c : r)
      if (!c.passed) out.push_back(c.name + ": " + c.message);
    return out;
  };
  CHECK(failures(checkComments(spec, run, {})).empty());

  SECTION("an unexpected warning, a missing error") {
    run.record->checkDiags.push_back({"p.bas", 3, 5, "warning", "'x' is never assigned"});
    spec.errors.insert({"p.bas", 2, "bad"});
    std::vector<std::string> f = failures(checkComments(spec, run, {}));
    CHECK(f == std::vector<std::string>{"check: rb check: missing error p.bas:2: bad",
                                        "check: rb check: unexpected warning p.bas:3: 'x' is never assigned",
                                        "check: rb check: exit status 0, expected 65",
                                        "run: rb run: errors differ from rb check's: none",
                                        "output: rb run printed output although the program was rejected: \"12\\n\"",
                                        "exit status: exit status 0, expected 65"});
  }
  SECTION("the runtime error, standard error and the exit status") {
    spec.runtime = Expected{"p.bas", 4, "division by zero"};
    run.record->error = DiagRecord{"dir/p.bas", 4, 9, "error", "division by zero"};
    run.process.code = 70;
    run.errors = "p.bas:4:9: error: division by zero\n";
    CHECK(failures(checkComments(spec, run, {})).empty());
    spec.stderrHas = {"no such thing"};
    CHECK(failures(checkComments(spec, run, {})) ==
          std::vector<std::string>{"stderr: standard error lacks \"no such thing\" (below)"});
    spec.stderrHas.clear();
    spec.exit = 3;
    CHECK(failures(checkComments(spec, run, {})).size() == 1);
  }
  SECTION("standard error nobody expected") {
    run.errors = "rb run: random seed 5\n";
    CHECK(failures(checkComments(spec, run, {})) ==
          std::vector<std::string>{"stderr: unexpected standard error (below)"});
  }
}

TEST_CASE("screens compare by the share of differing pixels", "[grade][checks]") {
  rb::render::RgbImage a;
  a.width = 10;
  a.height = 10;
  a.rgb.assign(300, 255);
  rb::render::RgbImage b = a;
  CHECK(compareImages(a, b)->differing == 0);
  b.set(3, 4, 0x000000);
  b.set(5, 5, 0xFF0000);
  std::optional<PixelDifference> d = compareImages(a, b);
  REQUIRE(d);
  CHECK(d->differing == 2);
  CHECK(d->share() == Approx(0.02));
  b.width = 5;
  CHECK_FALSE(compareImages(a, b));
}

TEST_CASE("pixel counts in messages", "[grade][checks]") {
  CHECK(pixels(37) == "37");
  CHECK(pixels(37.46) == "37.5");
  CHECK(pixels(-0.01) == "0");
  CHECK(pixels(std::numeric_limits<double>::infinity()) == "infinitely");
}

TEST_CASE("screens as runs compare as their pixels do", "[grade][checks]") {
  rb::render::RgbImage a;
  a.width = 40;
  a.height = 30;
  a.rgb.assign(40 * 30 * 3, 255);
  rb::render::RgbImage b = a;
  for (int x = 5; x < 25; ++x) b.set(x, 7, 0x00FF00);
  b.set(39, 29, 0x000000);
  a.set(10, 7, 0x00FF00);  // the same colour in both: not a difference
  a.set(0, 0, 0xFF0000);
  Screen sa = screenOf(a), sb = screenOf(b);
  CHECK(imageOf(sa).rgb == a.rgb);
  CHECK(imageOf(sb).rgb == b.rgb);
  std::optional<PixelDifference> runs = compareScreens(sa, sb), pixels = compareImages(a, b);
  REQUIRE(runs);
  REQUIRE(pixels);
  CHECK(runs->differing == pixels->differing);
  CHECK(runs->differing == 21);
  CHECK(compareScreens(sa, sa)->differing == 0);
  sb.width = 20;
  CHECK_FALSE(compareScreens(sa, sb));
}

TEST_CASE("output checks leave out what input showed unless prompts = true", "[grade][checks]") {
  Assignment a;
  References refs;
  RunOutcome sol = finished(kSquare, {400, 300}, "How many sides? 4\nsides: 4\n");
  sol.record->inputs = {{0, 16, 18}};
  refs.solution.push_back(sol);
  // Another prompt, and a print without a line end before it: the echo's line end ends it.
  RunOutcome run = finished(kSquare, {400, 300}, "Go! Sides please: 4\nsides: 4\n");
  run.record->inputs = {{4, 18, 20}};
  CHECK(comparedOutput(run, false) == "Go! \nsides: 4\n");
  CHECK(comparedOutput(sol, false) == "sides: 4\n");
  CHECK(printedOutput("abc", {{1, 2, 9}}) == "a\n");  // a mark past the end of a cut output
  Check same = check(Check::SolutionOutput);
  Check text = check(Check::Output);
  text.text = "sides: 4\n";
  a.checks = {same, text};
  RunOutcome quiet = finished(kSquare, {400, 300}, "Sides? 4\nsides: 4\n");
  quiet.record->inputs = {{0, 7, 9}};
  std::vector<CheckResult> r = checkAssignment(a, refs, {quiet}).checks;
  CHECK(r[0].passed);
  CHECK(r[1].passed);
  a.checks[0].prompts = a.checks[1].prompts = true;
  r = checkAssignment(a, refs, {quiet}).checks;
  CHECK_FALSE(r[0].passed);
  CHECK(r[0].message == "output differs at line 1: expected \"How many sides? 4\", got \"Sides? 4\" (the solution's output)");
  CHECK_FALSE(r[1].passed);
}

TEST_CASE("required, after, gates and tiers decide what counts", "[grade][checks]") {
  Assignment a;
  References refs;
  refs.aboutRobot = true;
  Check noError = check(Check::NoError);
  noError.required = true;
  Check ends = check(Check::EndsIn);
  Region box;
  box.x1 = 390, box.y1 = 290, box.x2 = 410, box.y2 = 310;
  ends.regions = {box};
  Check later = check(Check::Trail, 3);
  later.reference = kSquare;
  later.after = "ends-in";
  Check tiers = check(Check::Efficiency);
  tiers.measure = Check::Statements;
  tiers.tiers = {{10, 4}, {20, 2}};
  tiers.points = 4;
  a.checks = {noError, ends, later, tiers};

  Grading g = checkAssignment(a, refs, {finished(kSquare, {400, 300})});  // 17 statements
  CHECK(g.gate.empty());
  CHECK(g.checks[3].passed);
  CHECK(g.checks[3].earned == 2);  // the second tier

  RunOutcome away = finished(kThree, {520, 300});
  g = checkAssignment(a, refs, {away});
  CHECK_FALSE(g.checks[1].passed);
  CHECK_FALSE(g.checks[2].checked);
  CHECK(g.checks[2].message == "not checked: needs \"ends-in\", which did not pass");
  CHECK(g.checks[2].earned == 0);

  RunOutcome crash = finished(kSquare, {400, 300});
  crash.record->status = "error";
  crash.record->error = DiagRecord{"p.bas", 3, 1, "error", "division by zero"};
  g = checkAssignment(a, refs, {crash});
  CHECK_FALSE(g.checks[0].passed);
  CHECK(g.checks[1].passed);
  CHECK(g.checks[1].earned == 0);
  CHECK(g.checks[1].note == "not counted: the required check \"no-error\" did not pass");

  RunOutcome empty = finished({}, {0, 0});
  empty.record->statements = 0;
  g = checkAssignment(a, refs, {empty});
  CHECK(g.gate == "the program is empty: it has no statement");
  for (const CheckResult& c : g.checks) CHECK((!c.checked && c.earned == 0));

  RunOutcome still = finished({}, {400, 300});
  still.record->moves = 0;
  g = checkAssignment(a, refs, {still});
  CHECK(g.gate == "the robot never moved: the program never places, moves or turns it");
  refs.aboutRobot = false;
  CHECK(checkAssignment(a, refs, {still}).gate.empty());
}
