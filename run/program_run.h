#pragma once
// One run of a program, in the one sequence every way of running shares (headless `rb run`,
// `rb trace`, `rb render` and the live view `rb run --tui`):
//
//   load     read FILE and its includes, compile, print the load errors      (66, 65)
//   start    seed, sandbox, the Machine on the given Host, the observer,
//            the real robot of --real                                        (74)
//   run      the interpreter runs the program under --max-steps/--timeout
//   conclude name the seed when rb chose it, print the runtime error        (70)
//
// The callers differ only in their Host (where output goes, where keys come from, how time
// passes) and in what they do between the steps (the live view opens the terminal after load,
// shows the end, and restores the terminal before conclude prints anything).

#include <memory>
#include <string>

#include "machine/host.h"
#include "machine/interpreter.h"
#include "kernel_confine.h"
#include "machine/machine.h"
#include "program_loader.h"
#include "run_options.h"
#include "sandbox.h"

namespace rb::run {

struct ProgramRun {
  LoadedFile loaded;
  std::unique_ptr<Sandbox> sandbox;
  std::unique_ptr<Host> host;
  std::unique_ptr<Machine> machine;
  std::unique_ptr<Interpreter> interpreter;
  RunResult result;
  uint64_t seed = 0;
  bool ran = false;  ///< false when the program could not be loaded or started
  /// Set to false before conclude() when reaching --max-steps is not a failure (rb render
  /// uses it to choose the moment of its picture): then it is neither printed nor exit 70.
  bool stepLimitIsError = true;
  /// Set before start() when the screen's display list is needed afterwards (an SVG) or while
  /// the run goes on (the live view's text as characters).
  bool keepDisplayList = false;

  /// Loads and compiles FILE and prints its load errors on stderr, prefixed by `command`.
  /// Returns 0, or the exit code when it cannot run (66: no such file, 65: errors).
  int load(const char* command, const RunOptions& opts, const CompileOptions& compile);
  /// Builds the machine on `host` (kept here) and, with --real, connects the robot on --port.
  /// Returns "" or why the robot could not be connected (rb then exits 74).
  std::string start(const RunOptions& opts, std::unique_ptr<Host> runHost,
                    RobotObserver* observer);
  /// Runs the program to its end (or a limit, or a stop the host asks for).
  void run(const RunOptions& opts);
  /// After the run: names the seed when rb chose it and the program used it, prints the
  /// runtime error on stderr, and returns the exit code. A run the host stopped (RunStatus::
  /// Stopped) ends with `stoppedCode`.
  int conclude(const char* command, const RunOptions& opts, int stoppedCode) const;
};

// The steps' parts, for callers that need one alone.

/// Loads and compiles FILE and prints its load errors. Returns 0, or the exit code when it cannot
/// run (66: no such file, 65: errors).
int loadForRun(const char* command, const RunOptions& opts, const CompileOptions& compile,
               LoadedFile& loaded);
/// --seed, or a random seed.
uint64_t runSeed(const RunOptions& opts);
/// What the program may reach (--allow-files, --allow-spawn), its folder being FILE's.
std::unique_ptr<Sandbox> runSandbox(const RunOptions& opts);
/// The kernel's rules for a run from the command line: the program's folder tree and the
/// --allow-files folders to read and change, the library folders to read, the serial ports
/// (unless noPorts), the system folders with --allow-spawn; `outputs` are files rb itself writes
/// after the run (rb render -o, rb trace --out), whose folders may take new files.
KernelRules runKernelRules(const RunOptions& opts, const std::vector<std::string>& outputs = {});
/// Puts runKernelRules in force for the rest of the process (unless opts.confined). Returns ""
/// or, with --require-sandbox, why the kernel could not confine the run (rb then exits 70).
std::string confineRun(const char* command, const RunOptions& opts, const std::vector<std::string>& outputs = {});
/// The kernel's backstop under --max-memory (RLIMIT_DATA): the limit with room for rb itself.
uint64_t dataLimitBytes(uint64_t maxMemoryMiB);
/// --max-steps and --timeout.
RunLimits runLimits(const RunOptions& opts);
/// With --real: connects the robot on --port before the program starts. Returns "" or why it
/// could not (rb then exits with 74).
std::string connectRealRobot(const RunOptions& opts, Machine& machine);
/// After a run: names the seed when rb chose it and the program used it, so the run can be
/// repeated.
void reportSeed(const char* command, const RunOptions& opts, uint64_t seed, const Machine& machine);

}  // namespace rb::run
