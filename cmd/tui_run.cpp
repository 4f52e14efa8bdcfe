#include "tui_run.h"

#include <cstdio>

#include "curses_screen.h"
#include "diagnostic_output.h"
#include "exit_codes.h"
#include "headless_run.h"
#include "machine/interpreter.h"
#include "robot_port.h"
#include "tui_host.h"

namespace rb::cli {

namespace {

constexpr const char* kCommand = "rb run --tui";

/// The cell mode to start in: --cells when it names one the terminal can show, else half blocks
/// on a colour UTF-8 terminal, braille on a monochrome one, ASCII otherwise.
render::CellMode startMode(const render::CursesScreen& screen, const std::string& cells) {
  using render::CellMode;
  if (cells == "ascii") return CellMode::Ascii;
  if (cells == "braille" && screen.unicode()) return CellMode::Braille;
  if (cells == "half" && screen.unicode() && screen.colour()) return CellMode::HalfBlock;
  if (!screen.unicode()) return CellMode::Ascii;
  return screen.colour() ? CellMode::HalfBlock : CellMode::Braille;
}

std::string baseName(const std::string& path) {
  size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

int runTui(const RunOptions& opts) {
  if (!opts.eventsFile.empty() || !opts.keys.empty()) {
    std::fprintf(stderr,
                 "%s: --events and --keys feed headless runs; leave out --tui to use them\n",
                 kCommand);
    return exitcode::kUsage;
  }
  if (opts.file == "-") {
    std::fprintf(
        stderr,
        "%s: the program cannot come from standard input: the view reads the keyboard there\n",
        kCommand);
    return exitcode::kUsage;
  }
  CompileOptions compile;
  compile.lineTracing = true;  // single steps stop before every statement
  LoadedFile loaded;
  if (int code = loadForRun(kCommand, opts, compile, loaded)) return code;

  std::string why;
  std::unique_ptr<render::CursesScreen> screen = render::CursesScreen::open(why);
  if (!screen) {
    std::fprintf(stderr, "%s: no terminal (%s); run without --tui for a headless run\n", kCommand,
                 why.c_str());
    return exitcode::kIoError;
  }

  uint64_t seed = runSeed(opts);
  TuiHost host(*screen, baseName(opts.file), startMode(*screen, opts.cells));
  host.robotOpener = [&opts](int64_t port) { return openRobotPort(port, opts); };
  std::unique_ptr<Sandbox> sandbox = runSandbox(opts);
  host.setSystem(sandbox.get());
  Machine machine(host, seed);
  host.attach(machine);
  machine.setObserver(&host);
  if (std::string failed = connectRealRobot(opts, machine); !failed.empty()) {
    screen.reset();
    std::fprintf(stderr, "%s: %s\n", kCommand, failed.c_str());
    return exitcode::kIoError;
  }

  RunResult result;
  bool quit = false;
  try {
    Interpreter interp(*loaded.compiled, machine);
    result = interp.run(runLimits(opts));
    quit = result.status == RunStatus::Stopped;  // the user quit: the host stopped the run
    std::string error;
    if (result.error) {
      error = formatDiagnostic(loaded.program->sources, *result.error, DiagnosticStyle{false, true});
      error = error.substr(0, error.find('\n'));  // the heading line, without the include chain
    }
    host.showEnd(result, error);
  } catch (...) {
    screen.reset();  // never leave the terminal in raw mode
    throw;
  }
  screen.reset();  // the terminal is back to normal before anything is printed

  reportSeed(kCommand, opts, seed, machine);
  if (quit) return exitcode::kOk;  // the user ended the program on purpose
  if (result.error) {
    printDiagnostic(stderr, loaded.program->sources, *result.error, useColor(opts.color, stderr));
    return exitcode::kRuntime;
  }
  return exitcode::kOk;
}

}  // namespace rb::cli
