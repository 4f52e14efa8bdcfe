#pragma once
// Loading, compiling and running a program headless, shared by `rb run`, `rb trace` and
// `rb render`: they differ only in where program output goes and what they observe.

#include <cstdio>
#include <functional>
#include <memory>

#include "headless_host.h"
#include "machine/interpreter.h"
#include "machine/machine.h"
#include "program_loader.h"
#include "run_command.h"
#include "sandbox.h"

namespace rb::cli {

struct HeadlessRun {
  LoadedFile loaded;
  std::unique_ptr<Sandbox> sandbox;
  std::unique_ptr<HeadlessHost> host;
  std::unique_ptr<Machine> machine;
  RunResult result;
  uint64_t seed = 0;
  bool ran = false;  ///< false when the program could not be loaded
  /// Set to false before runHeadless when reaching --max-steps is not a failure (rb render
  /// uses it to choose the moment of its picture): then it is neither printed nor exit 70.
  bool stepLimitIsError = true;
  /// Set before runHeadless when the screen's display list is needed afterwards (an SVG).
  bool keepDisplayList = false;
};

/// Builds the scripted input that --events and --keys give (script.given is false when neither
/// is). On a bad script, prints the problem prefixed by `command` and returns rb's exit code
/// (66 for a missing file, 64 for a malformed script); returns 0 otherwise.
int loadInputScript(const char* command, const RunOptions& opts, InputScript& script);

// The steps every way of running a program shares (headless here, and the terminal view).

/// Loads and compiles FILE and prints its load errors. Returns 0, or the exit code when it cannot
/// run (66: no such file, 65: errors).
int loadForRun(const char* command, const RunOptions& opts, const CompileOptions& compile,
               LoadedFile& loaded);
/// --seed, or a random seed.
uint64_t runSeed(const RunOptions& opts);
/// What the program may reach (--allow-files, --allow-spawn), its folder being FILE's.
std::unique_ptr<Sandbox> runSandbox(const RunOptions& opts);
/// --max-steps and --timeout.
RunLimits runLimits(const RunOptions& opts);
/// With --real: connects the robot on --port before the program starts. Returns "" or why it
/// could not (rb then exits with 74).
std::string connectRealRobot(const RunOptions& opts, Machine& machine);
/// After a run: names the seed when rb chose it and the program used it, so the run can be
/// repeated.
void reportSeed(const char* command, const RunOptions& opts, uint64_t seed, const Machine& machine);

/// Runs FILE headless. Program output goes to `programOutput` (nullptr: discarded). Load
/// errors and the runtime error are printed on stderr prefixed by `command` ("rb render").
/// Returns the exit code rb should end with.
/// `onLine`, when set, is called before each statement (compile with lineTracing for it).
/// `onOutput`, when set, receives the program's output instead of `programOutput`.
int runHeadless(const char* command, const RunOptions& opts, const CompileOptions& compile,
                std::FILE* programOutput, RobotObserver* observer, HeadlessRun& run,
                std::function<void(SourceLoc)> onLine = nullptr,
                std::function<void(std::string_view)> onOutput = nullptr);

/// The statements a run executed, counting the one that failed. The interpreter counts steps
/// in blocks, so after a runtime error its count stops at the last jump; a program compiled
/// with lineTracing counts each statement as it starts (`started`), which is exact. At
/// --max-steps the interpreter's count (the limit) is the one to report.
uint64_t countedSteps(const RunResult& result, uint64_t started);

}  // namespace rb::cli
