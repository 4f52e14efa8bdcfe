// libFuzzer target over a whole run: the input bytes are a RobotBASIC program. It is loaded,
// compiled and run on a Machine (screen and robot included) under small step, time and memory
// bounds, with a host that answers every question (input lines, keys, clicks, message boxes)
// on a virtual clock; then the final screen goes through every picture writer (PNG encoding,
// SVG, the character view). A crash, a sanitizer report, or a run that overstays its limits
// (libFuzzer's -timeout) is a bug in rb.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "arena_view.h"
#include "lang/compiler.h"
#include "lang/loader.h"
#include "machine/builtins.h"
#include "machine/interpreter.h"
#include "machine/machine.h"
#include "machine/watchdog.h"
#include "png_writer.h"
#include "robot_view.h"
#include "svg_writer.h"

namespace {

/// Serves only the program itself: an #include of anything else is "not found".
class OneFileReader : public rb::SourceReader {
 public:
  explicit OneFileReader(const std::string& text) : text_(text) {}
  std::optional<std::string> find(const std::string& path) override {
    if (path == "fuzz.bas" || path == "inc.bas") return path;
    return std::nullopt;
  }
  std::optional<std::string> read(const std::string&) override { return text_; }

 private:
  const std::string& text_;
};

/// A host that answers everything at once and lets time pass only on its own clock, so that
/// a run is deterministic and never waits.
class AnsweringHost : public rb::Host {
 public:
  void output(std::string_view text) override { printed += text.size(); }
  std::optional<std::string> inputLine(std::string_view) override {
    if (++inputs > 50) return std::nullopt;  // input runs out: the program must stop cleanly
    return inputs % 2 ? "42" : "robot";
  }
  double clockMs() override { return ms += 1; }
  void wait(double delta) override {
    if (delta > 0 && delta < 1e12) ms += delta;
  }
  double wallSeconds() override {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  /// The run's time limit holds inside long statements too, as in `rb run`.
  void armWatchdog(const rb::WatchdogLimits& limits, rb::RunAlarms& alarms) override {
    watchdog.arm(start, limits, alarms, nullptr);
  }
  void disarmWatchdog() override { watchdog.disarm(); }
  int64_t heldKey(std::string_view) override { return (++keys % 3) ? 0 : 'a'; }
  int64_t waitKey(std::string_view) override { return 13; }
  rb::MouseState mouse(std::string_view) override { return {400, 300, 1}; }
  rb::MouseState waitClick(std::string_view) override { return {100, 100, 1}; }
  void messageBox(std::string_view, std::string_view) override {}

  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  size_t printed = 0;
  double ms = 0;
  int inputs = 0;
  int keys = 0;
  rb::Watchdog watchdog;
};

size_t sink = 0;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  OneFileReader reader(text);
  rb::DiagnosticList diags;
  std::unique_ptr<rb::LoadedProgram> loaded =
      rb::loadProgram("fuzz.bas", text, reader, rb::standardBuiltins(), rb::LoadOptions{}, diags);
  if (!loaded) __builtin_trap();
  std::unique_ptr<rb::Program> program = rb::compileProgram(*loaded, rb::CompileOptions{}, diags);
  if (!program) return 0;

  AnsweringHost host;
  rb::Machine machine(host, 1);
  rb::RunLimits limits;
  limits.maxSteps = 20000;
  limits.timeoutSeconds = 2;
  rb::Interpreter interp(*program, machine);
  rb::RunResult result = interp.run(limits);
  if (result.status == rb::RunStatus::RuntimeError && !result.error) __builtin_trap();

  // Every picture of the final screen.
  const rb::render::RobotView robot = rb::render::robotView(machine);
  const rb::Canvas& canvas = machine.canvas();
  sink += rb::render::encodePng(rb::render::composeImage(canvas.pixels(), robot, 1)).size();
  sink += rb::render::renderSvg(canvas, robot, 1).size();
  rb::render::ArenaOptions view;
  view.mode = static_cast<rb::render::CellMode>(size % 3);
  sink += rb::render::frameText(
              rb::render::renderArena(canvas.pixels(), canvas.background(), robot, view))
              .size();
  return 0;
}
