#pragma once
// Running a program headless, shared by `rb run`, `rb trace` and `rb render`: they differ only in
// where program output goes and what they observe. The steps are program_run.h's.

#include <cstdio>
#include <functional>
#include <memory>

#include "headless_host.h"
#include "program_run.h"

namespace rb::run {

/// A headless run: its host is a HeadlessHost.
struct HeadlessRun : ProgramRun {
  HeadlessHost& headlessHost() { return static_cast<HeadlessHost&>(*host); }
  /// Given to the host before the run: where each `input` left its mark in the output.
  std::function<void(const HeadlessHost::InputSpan&)> onInput;
  /// Given to the host before the run: sees the output that goes to the stream.
  std::function<void(std::string_view)> onCopy;
  /// Called once the machine is built, before the program runs: "" to go on, else why it may
  /// not run (printed after the command's name; rb then exits 70 and the program never runs).
  std::function<std::string(HeadlessRun&)> beforeRun;
  /// Called after the program ran, whatever its end, before its output is flushed.
  std::function<void(HeadlessRun&)> afterRun;
  /// Files the command writes after the run (rb render -o, rb trace --out): the kernel's rules
  /// let rb create them (kernel_confine.h).
  std::vector<std::string> outputs;
  /// The process's memory for --max-memory, opened before the run is confined; runHeadless
  /// makes it when the caller has not.
  std::shared_ptr<const ResidentMemory> memory;
};

/// Builds the scripted input that --events and --keys give (script.given is false when neither
/// is). On a bad script, prints the problem prefixed by `command` and returns rb's exit code
/// (66 for a missing file, 64 for a malformed script); returns 0 otherwise.
int loadInputScript(const char* command, const RunOptions& opts, InputScript& script);

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

}  // namespace rb::run
