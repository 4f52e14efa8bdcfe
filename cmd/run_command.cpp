#include "run_command.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <string>

#include "exit_codes.h"
#include "headless_run.h"
#include "tui_run.h"

namespace rb::cli {

namespace {
/// A number in [lo, hi], written as a person writes it: finite, whole when `whole`, the range in
/// the message as it is typed (CLI11's own checks let nan through and print their ranges as 300
/// digits). Every command takes its numbers through these, so each is checked the same way.
CLI::Validator numberIn(double lo, double hi, bool whole, const std::string& what, const std::string& range) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0;
        try {
          size_t used = 0;
          v = std::stod(text, &used);
          if (used != text.size()) return "'" + text + "' is not " + what;
        } catch (const std::exception&) {
          return "'" + text + "' is not " + what;
        }
        if (!std::isfinite(v) || v < lo || v > hi || (whole && v != std::floor(v)))
          return "'" + text + "' must be " + what + ", " + range;
        return "";
      },
      "");
}
}  // namespace

const CLI::Validator kSeconds = numberIn(0, 86400, false, "a number of seconds", "0 (no limit) to 86400 (a day)");
const CLI::Validator kLimitSeconds = numberIn(0.001, 86400, false, "a number of seconds", "0.001 to 86400 (a day)");
const CLI::Validator kPositiveSeconds =
    numberIn(0.001, 3600, false, "a number of seconds", "0.001 to 3600 (an hour)");
const CLI::Validator kStepCount =
    numberIn(0, 1e15, true, "a whole number of statements", "0 (no limit) to 1000000000000000");
const CLI::Validator kMebibytes = numberIn(0, 1 << 20, true, "a whole number of MiB", "0 (no limit) to 1048576 (1 TiB)");
const CLI::Validator kBaud = numberIn(50, 4000000, true, "a serial speed", "50 to 4000000");
const CLI::Validator kJobs = numberIn(1, 1024, true, "a number of programs at once", "1 to 1024");

namespace {

/// --speed: a factor from 1/64 to 64.
const CLI::Validator kSpeed(
    [](std::string& text) -> std::string {
      double v = 0;
      try {
        size_t used = 0;
        v = std::stod(text, &used);
        if (used != text.size()) return "'" + text + "' is not a number";
      } catch (const std::exception&) {
        return "'" + text + "' is not a number";
      }
      if (!std::isfinite(v) || v < 1.0 / 64 || v > 64)
        return "'" + text + "' must be a speed factor from 0.015625 (1/64) to 64";
      return "";
    },
    "X");

const CLI::Validator kNotEmpty(
    [](std::string& text) -> std::string { return text.empty() ? "must not be empty" : ""; }, "");
}  // namespace

void addRunLimitOptions(CLI::App& app, run::RunOptions& opts) {
  app.add_option("--color", opts.color,
                 "Colour the diagnostics: auto (on a terminal, unless NO_COLOR is set), always or never")
      ->check(CLI::IsMember({"auto", "always", "never"}));
  app.add_flag("--quiet", opts.quiet, "Leave out the warnings rb check would give (errors still show)");
  app.add_option("--seed", opts.seed,
                 "Seed for random numbers and rSlip (default: a random seed, reported on stderr "
                 "when the program uses it)");
  app.add_option("--max-steps", opts.maxSteps,
                 "Stop the program after N statements (0: no limit)")
      ->check(kStepCount)
      ->type_name("N");
  app.add_option("--timeout", opts.timeoutSeconds,
                 "Stop the program after SECONDS of real time (0: no limit; at most a day)")
      ->check(kSeconds)
      ->type_name("SECONDS");
  app.add_option("--max-memory", opts.maxMemoryMiB,
                 "Stop the program when rb uses more than MIB mebibytes of memory (default 1024; "
                 "0: no limit)")
      ->check(kMebibytes)
      ->type_name("MIB");
  CLI::Option* port = app.add_option(
      "--port", opts.port,
      "Serial port of the real robot: a number N (see man rb-run) or a device path; also used "
      "by the program's rCommPort")
      ->check(kNotEmpty);
  app.add_flag("--real", opts.real,
               "Drive a real robot on --port instead of the simulator (see man rb-run)")
      ->needs(port);
  app.add_option("--baud", opts.baud, "Serial speed for the real robot (default 9600)")
      ->check(kBaud);
  app.add_option("--robot-timeout", opts.robotTimeoutSeconds,
                 "Seconds to wait for each answer of the real robot (default 2; at most an hour)")
      ->check(kPositiveSeconds)
      ->type_name("SECONDS");
  app.add_option("--events", opts.eventsFile,
                 "Feed keys, mouse and dialog answers from a script file (see man rb-run)");
  app.add_option("--keys", opts.keys, "Feed these keys, one after another, as if typed");
  app.add_option("--allow-files", opts.allowFiles,
                 "Let the program's file built-ins reach DIR too (default: only the program's "
                 "own folder); repeatable")
      ->type_name("DIR");
  app.add_flag("--allow-spawn", opts.allowSpawn,
               "Let the program run other programs with Spawn (refused by default)");
  app.add_flag("--require-sandbox", opts.requireSandbox,
               "Refuse to run when the kernel cannot confine the program (no Landlock or seccomp: "
               "rb's own checks would be the only line)");
}

namespace {

int executeRun(const run::RunOptions& opts) {
  if (opts.tui) return tui::runTui(opts);
  run::HeadlessRun run;
  bool printed = false;
  run.onCopy = [&printed](std::string_view text) { printed = printed || !text.empty(); };
  int code = run::runHeadless("rb run", opts, CompileOptions{}, stdout, nullptr, run);
  // A program that only draws shows nothing on a terminal: say once where the picture is. Not
  // when the output goes to a pipe or a file (a script reads it), nor after an error.
  if (code == run::exitcode::kOk && run.ran && !printed && ::isatty(STDOUT_FILENO) &&
      (run.machine->canvas().version() != 0 || run.machine->robot().located())) {
    std::string file = opts.file == "-" ? "prog.bas" : opts.file;
    std::fprintf(stderr,
                 "rb run: the program drew on the screen and printed nothing; watch it with "
                 "'rb run --tui %s' or save the picture with 'rb render %s -o picture.png'\n",
                 file.c_str(), file.c_str());
  }
  return code;
}

}  // namespace

void addRunCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<run::RunOptions>();
  CLI::App* run = app.add_subcommand("run", "Run a RobotBASIC program (headless on the simulator)");
  if (!withOptions) return;
  run->add_option("file", opts->file, "Program file (- reads the program from standard input)")
      ->required();
  addRunLimitOptions(*run, *opts);
  CLI::Option* tui = run->add_flag(
      "--tui", opts->tui,
      "Show the program live in the terminal: the arena, the source around the running line, the "
      "variables; pause, step and break (see man rb-run)");
  run->add_option("--cells", opts->cells,
                  "Cell mode of --tui: ascii, half (half blocks), braille, or pixels (the screen "
                  "as a sixel image, on terminals that show them) (default: the finest "
                  "character mode the terminal can show; F6 switches)")
      ->check(CLI::IsMember({"ascii", "half", "braille", "pixels"}))
      ->needs(tui);
  run->add_option("--speed", opts->speed,
                  "Speed of --tui: X times real time (0.015625 to 64, default 1; F4/F5 halve and "
                  "double it)")
      ->check(kSpeed)
      ->needs(tui);
  run->add_flag("--paused", opts->paused, "Start --tui paused, before the first statement")
      ->needs(tui);
  run->add_option("--break", opts->breaks,
                  "Pause --tui before the statements of LINE (of FILE, for an included file); "
                  "repeatable")
      ->type_name("[FILE:]LINE")
      ->needs(tui);
  run->add_flag("--watch", opts->watch,
                "Run the program again in --tui each time it (or a file it includes) is saved, "
                "keeping the breakpoints and the view")
      ->needs(tui);
  run->footer(
      "Exit status: 0 finished (or --tui quit with F10), 64 bad usage, 65 the program has "
      "errors (nothing ran), 66 file not found, 70 runtime error or limit reached, 74 I/O error "
      "(also: --tui without a terminal that can show it), 130 --tui quit with Ctrl-C.");
  run->callback([opts, &exitCode] { exitCode = executeRun(*opts); });
}

}  // namespace rb::cli
