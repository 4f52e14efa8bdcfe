#include "tui_run.h"

#include <cstdio>

#include "curses_screen.h"
#include "exit_codes.h"
#include "program_run.h"
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
  ProgramRun run;
  if (int code = run.load(kCommand, opts, compile)) return code;

  std::string why;
  std::unique_ptr<render::CursesScreen> screen = render::CursesScreen::open(why);
  if (!screen) {
    std::fprintf(stderr, "%s: no terminal (%s); run without --tui for a headless run\n", kCommand,
                 why.c_str());
    return exitcode::kIoError;
  }

  auto host = std::make_unique<TuiHost>(*screen, baseName(opts.file), startMode(*screen, opts.cells));
  TuiHost& view = *host;
  view.robotOpener = [&opts](int64_t port) { return openRobotPort(port, opts); };
  if (std::string failed = run.start(opts, std::move(host), &view); !failed.empty()) {
    screen.reset();
    std::fprintf(stderr, "%s: %s\n", kCommand, failed.c_str());
    return exitcode::kIoError;
  }

  try {
    run.run(opts);
    std::string error;
    if (run.result.error) {
      error = formatDiagnostic(run.loaded.program->sources, *run.result.error);
      error = error.substr(0, error.find('\n'));
    }
    view.showEnd(run.result, error);
  } catch (...) {
    screen.reset();  // never leave the terminal in raw mode
    throw;
  }
  screen.reset();  // the terminal is back to normal before anything is printed
  return run.conclude(kCommand, opts, exitcode::kOk);  // quitting ends the run on purpose
}

}  // namespace rb::cli
