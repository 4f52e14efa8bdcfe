#include "tui_run.h"

#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "curses_screen.h"
#include "diagnostic_output.h"
#include "exit_codes.h"
#include "file_watch.h"
#include "program_loader.h"
#include "program_run.h"
#include "robot_port.h"
#include "tui_host.h"

namespace rb::tui {

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

/// The files the program was loaded from, for --watch: the main file (also when it could not be
/// read) and every file it includes.
std::vector<std::string> programFiles(const std::string& main, const run::LoadedFile& loaded) {
  std::vector<std::string> files = {main};
  if (loaded.program)
    for (uint32_t i = 1; i < loaded.program->sources.size(); ++i)
      files.push_back(loaded.program->sources.file(i).name());
  return files;
}

/// Why a program could not be loaded, as the view shows it: the heading line of each error.
std::string loadErrorText(const std::string& file, const run::LoadedFile& loaded) {
  if (!loaded.program) return "cannot read '" + file + "': " + loaded.readError;
  std::string out;
  for (const Diagnostic& d : loaded.diags.all()) {
    if (d.severity != Severity::Error) continue;
    if (!out.empty()) out += '\n';
    out += formatDiagnostic(loaded.program->sources, d, DiagnosticStyle{false, true});
  }
  return out;
}

/// The same in full, on standard error after the view closed, as rb run prints them.
void printLoadErrors(const run::RunOptions& opts, const run::LoadedFile& loaded) {
  if (!loaded.program) {
    std::fprintf(stderr, "%s: cannot read '%s': %s\n", kCommand, opts.file.c_str(),
                 loaded.readError.c_str());
    return;
  }
  diagnostics::DiagOutputOptions out;
  out.color = diagnostics::useColor(opts.color, stderr);
  diagnostics::DiagnosticReport report(stderr, out);
  report.add(loaded.program->sources, loaded.diags, true);
  report.finish();
}

/// Puts the breakpoints a restart keeps on the program as it is now: by file name, each on its
/// line or (that line holding no statement any more) the next that holds one; one whose file is
/// gone, or with no statement on or after its line, is dropped. Returns what changed, for the
/// title ("" when nothing did).
std::string placeKept(const std::vector<NamedBreakpoint>& kept, const SourceSet& sources,
                      const StatementLines& statements, Debugger& debugger) {
  std::vector<std::string> notes;
  for (const NamedBreakpoint& b : kept) {
    uint32_t file = 0;
    while (file < sources.size() && sources.file(file).name() != b.file) ++file;
    std::string where = "line " + std::to_string(b.line);
    if (file != 0) where += " of " + baseName(b.file);
    if (file == sources.size()) {
      notes.push_back("breakpoint on " + where + " dropped: the program no longer includes it");
      continue;
    }
    BreakpointPlace place = placeBreakpoint(statements, file, b.line);
    if (place.line == 0) {
      notes.push_back("breakpoint on " + where + " dropped: no statement on or after it");
      continue;
    }
    if (place.moved)
      notes.push_back("breakpoint moved: line " + std::to_string(b.line) + " -> " +
                      std::to_string(place.line) + " (no statement on " + std::to_string(b.line) +
                      ")");
    debugger.addBreakpoint(file, place.line);
  }
  if (notes.empty()) return "";
  if (notes.size() == 1) return notes[0];
  return notes[0] + " (and " + std::to_string(notes.size() - 1) + " more)";
}

}  // namespace

int runTui(const run::RunOptions& opts) {
  if (!opts.eventsFile.empty() || !opts.keys.empty()) {
    std::fprintf(stderr,
                 "%s: --events and --keys feed headless runs; leave out --tui to use them\n",
                 kCommand);
    return run::exitcode::kUsage;
  }
  if (opts.file == "-") {
    std::fprintf(
        stderr,
        "%s: the program cannot come from standard input: the view reads the keyboard there\n",
        kCommand);
    return run::exitcode::kUsage;
  }
  CompileOptions compile;
  compile.lineTracing = true;  // single steps stop before every statement
  run::LoadedFile loaded;
  if (opts.watch) {
    // Watching, a program with errors still opens the view, which waits for the fix to be saved.
    loaded = run::loadFile(opts.file, compile, false, false, opts.allowFiles);
    if (loaded.exitCode == run::exitcode::kNoInput) {
      printLoadErrors(opts, loaded);
      return run::exitcode::kNoInput;
    }
    if (loaded.compiled && !opts.quiet)
      run::printWarningLines(kCommand, opts.file, loaded.program->sources, loaded.diags,
                             diagnostics::useColor(opts.color, stderr));
  } else if (int code = run::loadForRun(kCommand, opts, compile, loaded)) {
    return code;
  }

  std::string why;
  std::unique_ptr<render::CursesScreen> screen;
  TuiSettings settings;
  {
    // Breakpoints go on statements: one asked for on a line without one (a comment, a blank
    // line, a label) moves to the next line that has one, and says so here, before the view
    // hides the terminal, and in the view's title.
    const SourceSet& sources = loaded.program->sources;
    std::optional<StatementLines> statements;
    if (loaded.compiled) statements.emplace(*loaded.compiled);
    std::vector<std::string> moved;
    for (const std::string& b : opts.breaks) {
      std::optional<std::pair<uint32_t, uint32_t>> at = breakpointLine(b, sources);
      if (!at) {
        std::fprintf(stderr, "%s: --break %s: no such line in the program\n", kCommand, b.c_str());
        return run::exitcode::kUsage;
      }
      uint32_t line = at->second;
      // (A program that does not load yet, with --watch, places them when it does.)
      if (statements) {
        BreakpointPlace place = placeBreakpoint(*statements, at->first, at->second);
        if (place.line == 0) {
          std::fprintf(stderr, "%s: --break %s: %s\n", kCommand, b.c_str(), place.note.c_str());
          return run::exitcode::kUsage;
        }
        if (place.moved) {
          std::fprintf(stderr, "%s: --break %s: %s\n", kCommand, b.c_str(), place.note.c_str());
          moved.push_back("breakpoint moved: line " + std::to_string(at->second) + " -> " +
                          std::to_string(place.line) + " (no statement on " +
                          std::to_string(at->second) + ")");
        }
        line = place.line;
      }
      settings.breakpoints.push_back({sources.file(at->first).name(), line});
    }
    if (moved.size() == 1) settings.notice = moved[0];
    if (moved.size() > 1)
      settings.notice =
          std::to_string(moved.size()) + " breakpoints moved to the next line with a statement";

    screen = render::CursesScreen::open(why);
    if (!screen) {
      std::fprintf(stderr, "%s: no terminal (%s); run without --tui for a headless run\n",
                   kCommand, why.c_str());
      return run::exitcode::kIoError;
    }
  }

  settings.fileName = baseName(opts.file);
  settings.mode = startMode(*screen, opts.cells);
  settings.pixels = opts.cells == "pixels";
  settings.speed = opts.speed;
  settings.paused = opts.paused;
  settings.watching = opts.watch;
  // A restart runs the program with the seed of the first run: the same random numbers, so a
  // run repeats until the program changes.
  run::RunOptions runOpts = opts;
  runOpts.seed = run::runSeed(opts);
  std::unique_ptr<FileWatch> watch;
  if (opts.watch) watch = std::make_unique<FileWatch>();
  // The terminal is open and the program loaded: from here on the kernel's rules hold (a
  // restart with --watch reads the program's folder again, which they allow).
  if (std::string refused = run::confineRun(kCommand, opts); !refused.empty()) {
    screen.reset();
    std::fprintf(stderr, "%s\n", refused.c_str());
    return run::exitcode::kRuntime;
  }
  std::unique_ptr<run::ProgramRun> run;
  TuiHost* view = nullptr;  // the last run's view (its run owns it)
  bool notLoaded = false;   // the view closed while the program could not be loaded
  int quitCode = 0;

  try {
    for (;;) {
      if (watch) watch->watch(programFiles(opts.file, loaded));
      if (!loaded.compiled) {
        // Nothing runs: the last run (its robot port, its memory) is over.
        run.reset();
        view = nullptr;
        TuiHost host(*screen, settings);
        host.fileWatch = watch.get();
        if (loaded.program) host.showSources(&loaded.program->sources);
        SourceLoc first;
        for (const Diagnostic& d : loaded.diags.all())
          if (d.severity == Severity::Error && !first.valid()) first = d.loc;
        host.showLoadErrors(loadErrorText(opts.file, loaded), first);
        if (!host.restartRequested()) {
          notLoaded = true;
          quitCode = host.quitCode();
          break;
        }
        settings = host.nextSettings();
        loaded = run::loadFile(opts.file, compile, false, false, opts.allowFiles);
        continue;
      }
      run.reset();  // the last run's robot port is closed before the next run opens it
      run = std::make_unique<run::ProgramRun>();
      run->loaded = std::move(loaded);
      const SourceSet& sources = run->loaded.program->sources;
      auto host = std::make_unique<TuiHost>(*screen, settings);
      view = host.get();
      std::string moved = placeKept(settings.breakpoints, sources,
                                    StatementLines(*run->loaded.compiled), view->debugger());
      if (!moved.empty()) view->startNotice(moved);
      view->fileWatch = watch.get();
      view->robotOpener = [&opts](int64_t port) { return run::openRobotPort(port, opts); };
      run->keepDisplayList = true;  // the text the program draws, shown as characters
      if (std::string failed = run->start(runOpts, std::move(host), view); !failed.empty()) {
        screen.reset();
        std::fprintf(stderr, "%s: %s\n", kCommand, failed.c_str());
        return run::exitcode::kIoError;
      }
      view->watch(*run->interpreter, sources);
      run->run(runOpts);
      std::string error;
      if (run->result.error) {
        error = formatDiagnostic(sources, *run->result.error, DiagnosticStyle{false, true});
        error = error.substr(0, error.find('\n'));  // the heading line, without the include chain
      }
      view->showEnd(run->result, error);
      if (!view->restartRequested()) break;
      // The program as it is on disk now: a restart takes the edits in.
      settings = view->nextSettings();
      loaded = run::loadFile(opts.file, compile, false, false, opts.allowFiles);
    }
  } catch (...) {
    screen.reset();  // never leave the terminal in raw mode
    throw;
  }
  screen.reset();  // the terminal is back to normal before anything is printed
  if (notLoaded) {
    printLoadErrors(opts, loaded);
    if (quitCode == TuiHost::kInterruptedExit) return quitCode;
    return loaded.program ? run::exitcode::kRejected : run::exitcode::kNoInput;
  }
  // What the program printed, on the normal screen, as a headless run prints it.
  const std::string& out = view->transcript();
  std::fwrite(out.data(), 1, out.size(), stdout);
  if (!out.empty() && out.back() != '\n') std::fputc('\n', stdout);
  if (view->transcriptCut())
    std::fprintf(stderr, "%s: the program printed more than the view keeps; the rest is cut\n",
                 kCommand);
  std::fflush(stdout);
  // Quitting ends the run on purpose: 0 for the quit keys, 130 for Ctrl-C. The seed is named
  // as the first run's (every restart used it).
  return run->conclude(kCommand, opts, view->quitCode());
}

}  // namespace rb::tui
