#pragma once
// What a run of a program from the command line may do and how: the options `rb run`, `rb
// trace`, `rb render` and `rb test`'s runs share (cmd/run_command.cpp declares them), which the
// run sequence (program_run.h), the headless host and the live view read.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rb::run {

/// Options every subcommand that runs a program shares (run, trace, render).
struct RunOptions {
  std::string file;
  std::optional<uint64_t> seed;
  uint64_t maxSteps = 0;
  double timeoutSeconds = 0;
  uint64_t maxMemoryMiB = 1024;  ///< --max-memory (0: no limit)
  // A real robot (drivers/): --real connects before the program starts; --port also names the
  // port a program's rCommPort opens.
  bool real = false;
  std::string port;
  int baud = 9600;
  double robotTimeoutSeconds = 2;
  // Scripted input for headless runs (--events FILE, --keys TEXT).
  std::string eventsFile;
  std::string keys;
  // What the program may reach: files in its own folder and these (--allow-files DIR); other
  // programs only with --allow-spawn.
  std::vector<std::string> allowFiles;
  bool allowSpawn = false;
  /// rb test's runs: no serial device unless the grader allows it (the assignment's `ports`, or
  /// --trust-comments). `rb run` opens the port a program names, as RobotBASIC does.
  bool noPorts = false;
  /// The kernel's rules (kernel_confine.h) are in force already: rb test's jobs confine
  /// themselves before loading the program, so the run does not confine again.
  bool confined = false;
  /// Refuse to run when the kernel cannot confine the program (--require-sandbox).
  bool requireSandbox = false;
  // rb run only: the live terminal view, its cell mode (ascii, half, braille or pixels; empty:
  // the best the terminal can show), its speed, whether it starts paused, and breakpoints
  // (LINE or FILE:LINE, --break, repeatable).
  bool tui = false;
  std::string cells;
  double speed = 1;
  bool paused = false;
  std::vector<std::string> breaks;
  bool watch = false;  ///< --watch: run the program again in the view when it is saved
  // Diagnostics: --color auto|always|never; --quiet leaves out the load warnings.
  std::string color = "auto";
  bool quiet = false;
};

}  // namespace rb::run
