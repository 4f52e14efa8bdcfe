#pragma once
// The Host of a headless run: program output to a stream, `input` lines from a stream, and a
// virtual clock that only moves when the program waits (delay, robot motion at rSpeed), reads
// timer() or reads input, so runs are fast and repeatable. Keys, the mouse and dialog answers
// come from scripted input (--events, --keys: core/input/input_script.h).

#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <istream>
#include <memory>

#include "machine/host.h"
#include "machine/machine.h"
#include "machine/watchdog.h"
#include "input/input_script.h"

namespace rb::run {

/// The process's resident memory, read from /proc/self/statm through a descriptor opened when
/// this is made: so it still reads once the kernel's rules (kernel_confine.h) hide /proc.
class ResidentMemory {
 public:
  ResidentMemory();
  ~ResidentMemory();
  ResidentMemory(const ResidentMemory&) = delete;
  ResidentMemory& operator=(const ResidentMemory&) = delete;
  /// Bytes resident now, 0 when unknown.
  uint64_t bytes() const;

 private:
  int fd_ = -1;
};

class HeadlessHost : public Host {
 public:
  /// Program output goes to `out` (nullptr: discarded), `input` reads lines from `in`.
  /// With a script given, `input` reads its lines from the script instead of `in`.
  HeadlessHost(std::FILE* out, std::istream& in, InputScript script = {});
  ~HeadlessHost() override;

  void attachMachine(Machine& machine) override;
  void output(std::string_view text) override;
  std::optional<std::string> inputLine(std::string_view prompt) override;
  double clockMs() override;
  void wait(double ms) override;
  double wallSeconds() override;
  /// A watchdog thread raises the alarms: the deadline when the time is up (`input` on a silent
  /// terminal or pipe then ends too), memory when the process's resident memory, sampled every
  /// 10 ms, passes the limit.
  void armWatchdog(const WatchdogLimits& limits, RunAlarms& alarms) override;
  uint64_t memoryInUse() override;
  void disarmWatchdog() override;
  /// Where memoryInUse() and the watchdog read the process's memory (made before the process is
  /// confined); none: no memory limit can be kept.
  std::shared_ptr<const ResidentMemory> memory;
  /// When >= 0, `input` reads this file descriptor itself (instead of the stream), waiting with
  /// poll() so that --timeout ends a run that waits for a line nobody types.
  int inputFd = -1;
  /// Whether `input` writes the line it read and a line end after the prompt, as the screen
  /// shows it (docs/language.md): on when the line comes from a pipe, a file or a script; off
  /// when a terminal already echoed what the user typed.
  bool echoInput = true;
  /// Where one `input` left its mark in the output, as byte offsets from the output's start:
  /// the prompt from `start` to `promptEnd`, then the echo of the line read up to `end`.
  struct InputSpan {
    uint64_t start = 0, promptEnd = 0, end = 0;
    std::string_view line;  ///< the line read (without its line end), valid during the call
  };
  /// Called after each `input` that read a line.
  std::function<void(const InputSpan&)> inputHook;
  /// When set, `input` reads its lines from here (no echo): a grader's program reading what
  /// the student's printed.
  std::function<std::optional<std::string>()> inputSource;
  int64_t heldKey(std::string_view who) override { return script_.heldKey(who); }
  int64_t waitKey(std::string_view who) override { return script_.waitKey(who); }
  MouseState mouse(std::string_view who) override { return script_.mouse(who); }
  MouseState waitClick(std::string_view who) override { return script_.waitClick(who); }
  void updateControls(Controls& controls, std::string_view who) override {
    script_.updateControls(controls, who);
  }
  void messageBox(std::string_view, std::string_view) override { script_.messageBox("MsgBox"); }
  void onLine(SourceLoc loc) override {
    if (lineHook) lineHook(loc);
  }
  void flush();
  /// A failed write of program output (a full disk, a closed pipe) stops the run: the output
  /// is lost, so going on would only waste time. errno of the failure, 0 when none.
  int writeError() const { return writeError_; }
  bool poll() override { return writeError_ == 0; }

  std::unique_ptr<RobotLink> openRobot(int64_t port) override {
    if (robotOpener) return robotOpener(port);
    return Host::openRobot(port);
  }

  /// Called before each statement of a program compiled for line tracing.
  std::function<void(SourceLoc)> lineHook;
  /// When set, program output goes here instead of the output stream (rb trace's events).
  std::function<void(std::string_view)> outputHook;
  /// When set, also sees the output that goes to the stream.
  std::function<void(std::string_view)> copyHook;
  /// Opens a real robot's port for rCommPort.
  std::function<std::unique_ptr<RobotLink>(int64_t)> robotOpener;

 private:
  std::FILE* out_;
  std::istream& in_;
  std::string buffer_;
  uint64_t written_ = 0;  ///< bytes of output written to the stream so far
  int writeError_ = 0;
  double virtualMs_ = 0;
  ScriptedInput script_;  ///< plays on virtualMs_
  std::chrono::steady_clock::time_point start_;
  std::optional<std::string> readInput();
  std::optional<std::string> readLineFromFd();
  std::string fdBuffer_;    ///< bytes read from inputFd past the last line returned
  bool fdEnded_ = false;
  RunAlarms* alarms_ = nullptr;
  Watchdog watchdog_;
};

}  // namespace rb::run
