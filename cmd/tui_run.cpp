#include "tui_run.h"

#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "curses_screen.h"
#include "diagnostic_output.h"
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

/// --break LINE or FILE:LINE: the file's index in the program's sources and the line; nullopt
/// when no file of the program has that name or the line is past its end.
std::optional<std::pair<uint32_t, uint32_t>> breakpointLine(const std::string& spec,
                                                            const SourceSet& sources) {
  std::string file, line = spec;
  if (size_t colon = spec.rfind(':'); colon != std::string::npos) {
    file = spec.substr(0, colon);
    line = spec.substr(colon + 1);
  }
  if (line.empty() || line.size() > 9 || line.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  uint32_t n = static_cast<uint32_t>(std::stoul(line));
  for (uint32_t i = 0; i < sources.size(); ++i) {
    const SourceFile& f = sources.file(i);
    bool named = file.empty() ? i == 0
                              : f.name() == file || (f.name().size() > file.size() &&
                                                     f.name().ends_with("/" + file));
    if (named && n >= 1 && n <= f.lineCount()) return std::make_pair(i, n);
  }
  return std::nullopt;
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

  // Breakpoints go on statements: one asked for on a line without one (a comment, a blank
  // line, a label) moves to the next line that has one, and says so here, before the view
  // hides the terminal, and in the view's title.
  const SourceSet& sources = run.loaded.program->sources;
  StatementLines statements(*run.loaded.compiled);
  std::vector<std::pair<uint32_t, uint32_t>> breaks;
  std::vector<std::string> moved;
  for (const std::string& b : opts.breaks) {
    std::optional<std::pair<uint32_t, uint32_t>> at = breakpointLine(b, sources);
    if (!at) {
      std::fprintf(stderr, "%s: --break %s: no such line in the program\n", kCommand, b.c_str());
      return exitcode::kUsage;
    }
    BreakpointPlace place = placeBreakpoint(statements, at->first, at->second);
    if (place.line == 0) {
      std::fprintf(stderr, "%s: --break %s: %s\n", kCommand, b.c_str(), place.note.c_str());
      return exitcode::kUsage;
    }
    if (place.moved) {
      std::fprintf(stderr, "%s: --break %s: %s\n", kCommand, b.c_str(), place.note.c_str());
      moved.push_back("breakpoint moved: line " + std::to_string(at->second) + " -> " +
                      std::to_string(place.line) + " (no statement on " +
                      std::to_string(at->second) + ")");
    }
    breaks.emplace_back(at->first, place.line);
  }

  std::string why;
  std::unique_ptr<render::CursesScreen> screen = render::CursesScreen::open(why);
  if (!screen) {
    std::fprintf(stderr, "%s: no terminal (%s); run without --tui for a headless run\n", kCommand,
                 why.c_str());
    return exitcode::kIoError;
  }

  TuiSettings settings;
  settings.fileName = baseName(opts.file);
  settings.mode = startMode(*screen, opts.cells);
  settings.pixels = opts.cells == "pixels";
  settings.speed = opts.speed;
  settings.paused = opts.paused;
  auto host = std::make_unique<TuiHost>(*screen, settings);
  TuiHost& view = *host;
  view.robotOpener = [&opts](int64_t port) { return openRobotPort(port, opts); };
  for (auto [file, line] : breaks) view.debugger().addBreakpoint(file, line);
  if (!moved.empty()) view.startNotice(moved.size() == 1 ? moved[0] : std::to_string(moved.size()) + " breakpoints moved to the next line with a statement");
  run.keepDisplayList = true;  // the text the program draws, shown as characters
  if (std::string failed = run.start(opts, std::move(host), &view); !failed.empty()) {
    screen.reset();
    std::fprintf(stderr, "%s: %s\n", kCommand, failed.c_str());
    return exitcode::kIoError;
  }
  view.watch(*run.interpreter, sources);

  try {
    run.run(opts);
    std::string error;
    if (run.result.error) {
      error = formatDiagnostic(sources, *run.result.error, DiagnosticStyle{false, true});
      error = error.substr(0, error.find('\n'));  // the heading line, without the include chain
    }
    view.showEnd(run.result, error);
  } catch (...) {
    screen.reset();  // never leave the terminal in raw mode
    throw;
  }
  screen.reset();  // the terminal is back to normal before anything is printed
  // What the program printed, on the normal screen, as a headless run prints it.
  const std::string& out = view.transcript();
  std::fwrite(out.data(), 1, out.size(), stdout);
  if (!out.empty() && out.back() != '\n') std::fputc('\n', stdout);
  if (view.transcriptCut())
    std::fprintf(stderr, "%s: the program printed more than the view keeps; the rest is cut\n",
                 kCommand);
  std::fflush(stdout);
  // Quitting ends the run on purpose: 0 for the quit keys, 130 for Ctrl-C.
  return run.conclude(kCommand, opts, view.quitCode());
}

}  // namespace rb::cli
