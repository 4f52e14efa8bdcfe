#include "machine/recording.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "machine/test_support.h"

using namespace rb;

namespace {

/// A host that feeds a recording, as the hosts of the replays do.
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

/// Runs `text` compiled with line tracing, feeding `rec`.
RunResult record(const std::string& text, Recording& rec, RunLimits limits = {}) {
  test::MemoryReader reader;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", text, reader, standardBuiltins(), {}, diags);
  CompileOptions compile;
  compile.lineTracing = true;
  auto program = compileProgram(*loaded, compile, diags);
  REQUIRE(program);
  RecordingHost host(rec);
  Machine machine(host, 1);
  host.machine = &machine;
  Interpreter interp(*program, machine);
  RunResult result = interp.run(limits);
  rec.finish(machine, result);
  return result;
}

const char* kSquare =
    "rLocate 400,300\nrInvisible GREEN\nLineWidth 4\nrPen DOWN\nfor n = 1 to 4\n  rForward 120\n"
    "  rTurn 90\nnext\nprint \"perimeter \" + 4 * 120\n";

}  // namespace

TEST_CASE("a short run is recorded statement by statement", "[machine][recording]") {
  Recording rec;
  record(kSquare, rec);
  REQUIRE(rec.finished());
  CHECK(rec.totalSteps() == 18);
  REQUIRE(rec.steps().size() == 19);  // every statement and the end
  CHECK(rec.stepStride() == 1);
  CHECK(rec.steps()[0].loc.line == 1);
  CHECK_FALSE(rec.steps()[0].located);
  CHECK(rec.steps()[1].located);  // after rLocate
  CHECK(rec.steps()[1].x == 400);
  CHECK(rec.steps().back().loc.line == 0);  // the end
  CHECK(rec.steps().back().x == 400);
  CHECK(rec.steps().back().y == 300);
  CHECK(rec.output() == "perimeter 480\n");
  CHECK(rec.steps().back().output == 14);
  // A keyframe each time the screen changed: the white screen, after each side, the end.
  CHECK(rec.frames().size() == 6);  // and the text print drew
  // The first side, drawn by statement 6 (step 5), shows from the statement after it.
  const RecordedStep& afterSide = rec.steps()[6];
  std::vector<Colour> screen = rec.screen(afterSide.frame);
  CHECK(screen[static_cast<size_t>(240) * Canvas::kWidth + 400] == colours::kGreen);
  CHECK(rec.screen(rec.steps()[5].frame)[static_cast<size_t>(240) * Canvas::kWidth + 400] == colours::kWhite);
  CHECK(rec.stepAt(6) == 6);
}

TEST_CASE("a long run stays within its budget, evenly sampled", "[machine][recording]") {
  Recording rec(size_t{8} << 20);  // 8 MiB
  std::string roam =
      "rLocate 400,300\nrInvisible RED\nrPen DOWN\nfor i = 1 to 100000\n  if rFeel() then rTurn 77 else rForward 3\n"
      "  c = i % 15\n  LineWidth 1 + i % 3\nnext\n";
  RunResult r = record(roam, rec);
  CHECK(r.status == RunStatus::Finished);
  CHECK(rec.totalSteps() > 300000);
  CHECK(rec.bytes() <= (size_t{8} << 20));
  CHECK(rec.stepStride() > 1);
  CHECK(rec.steps().size() > 1000);
  // Evenly spread: the kept steps are stride apart.
  for (size_t i = 1; i + 1 < rec.steps().size(); ++i)
    CHECK(rec.steps()[i].step - rec.steps()[i - 1].step == rec.stepStride());
  CHECK(rec.frames().size() > 10);
  for (const RecordedStep& s : rec.steps()) REQUIRE(s.frame < rec.frames().size());
  for (size_t i = 1; i < rec.steps().size(); ++i) CHECK(rec.frames()[rec.steps()[i].frame].step <= rec.steps()[i].step);
  // The last frame is the final screen.
  CHECK(rec.steps().back().frame + 1 == rec.frames().size());
}

TEST_CASE("screens as runs of colour numbers", "[machine][recording]") {
  std::vector<Colour> px = {1, 1, 1, 2, 3, 3};
  std::vector<ScreenRun> runs = screenRuns(px.data(), px.size());
  CHECK(runs == std::vector<ScreenRun>{{3, 1}, {1, 2}, {2, 3}});
  CHECK(screenFromRuns(runs, px.size()) == px);
}


TEST_CASE("every kept frame is the screen as its statement starts, also after thinning", "[machine][recording]") {
  // A host that remembers a fingerprint of the screen before each statement that changed it.
  struct Checking : RecordingHost {
    using RecordingHost::RecordingHost;
    std::map<uint64_t, uint64_t> seen;  // step -> fingerprint
    uint64_t version = 0, steps = 0;
    void onLine(SourceLoc loc) override {
      const Canvas& c = machine->canvas();
      if (c.version() != version) {
        version = c.version();
        uint64_t h = 1469598103934665603ull;
        for (Colour px : c.pixels()) h = (h ^ px) * 1099511628211ull;
        seen[steps] = h;
      }
      ++steps;
      RecordingHost::onLine(loc);
    }
  };
  std::string scribble =
      "rLocate 400,300\nrPen DOWN\nfor i = 1 to 3000\n  LineWidth 1 + i % 4\n"
      "  Line (i * 7) % 800, (i * 13) % 600, (i * 11) % 800, (i * 3) % 600, 1 + i % 3, i % 16\n"
      "  if i % 500 = 0 then Rectangle i / 10, 10, i / 10 + 30, 40, i % 16, i % 16\nnext\n";
  Recording rec(size_t{24} << 20);  // small for this busy screen: frames are thinned
  test::MemoryReader reader;
  DiagnosticList diags;
  auto loaded = loadProgram("test.bas", scribble, reader, standardBuiltins(), {}, diags);
  CompileOptions compile;
  compile.lineTracing = true;
  auto program = compileProgram(*loaded, compile, diags);
  REQUIRE(program);
  Checking host(rec);
  Machine machine(host, 1);
  host.machine = &machine;
  Interpreter interp(*program, machine);
  rec.finish(machine, interp.run({}));
  INFO("frames " << rec.frames().size() << " bytes " << rec.bytes() << " steps " << rec.totalSteps());
  CHECK(rec.frameStride() > 1);
  REQUIRE(rec.frames().size() > 2);
  for (size_t f = 0; f + 1 < rec.frames().size(); ++f) {
    std::vector<Colour> px = rec.screen(f);
    uint64_t h = 1469598103934665603ull;
    for (Colour c : px) h = (h ^ c) * 1099511628211ull;
    auto at = host.seen.upper_bound(rec.frames()[f].step);  // the screen in effect at that step
    REQUIRE(at != host.seen.begin());
    --at;
    INFO("frame " << f << " at step " << rec.frames()[f].step);
    CHECK(h == at->second);
  }
  std::vector<Colour> last = rec.screen(rec.frames().size() - 1);
  CHECK(std::equal(last.begin(), last.end(), machine.canvas().pixels().begin()));
}

TEST_CASE("with flip on, the frames are the screen a viewer sees: the last flip's", "[machine][recording]") {
  Recording rec;
  record("flip on\nrectangle 0, 0, 100, 100, RED, RED\nx = 1\nflip\nrectangle 200, 200, 300, 300, BLUE, BLUE\n"
         "flip off\nx = 2\n",
         rec);
  REQUIRE(rec.steps().size() == 8);
  auto at = [&rec](size_t step, int x, int y) {
    return rec.screen(rec.steps()[step].frame)[static_cast<size_t>(y) * Canvas::kWidth + static_cast<size_t>(x)];
  };
  CHECK(at(2, 50, 50) == colours::kWhite);  // drawn, not flipped yet
  CHECK(at(4, 50, 50) == colours::kRed);    // flipped
  CHECK(at(5, 250, 250) == colours::kWhite);
  CHECK(at(6, 250, 250) == colours::kBlue);  // flip off shows the canvas again
  CHECK(at(7, 250, 250) == colours::kBlue);
}

TEST_CASE("the robot's pose is kept as the robot has it, not rounded", "[machine][recording]") {
  Recording rec;
  record("rLocate 400, 300\nrTurn 77\nrForward 3\nrTurn 0.1\n", rec);
  const RecordedStep& end = rec.steps().back();
  double rad = 77 * 3.14159265358979323846 / 180;
  CHECK(end.x == Approx(400 + 3 * std::sin(rad)).margin(1e-9));
  CHECK(end.x != static_cast<double>(static_cast<float>(end.x)));  // a float would round it
  CHECK(end.heading == Approx(77.1));
}
