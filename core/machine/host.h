#pragma once
// Everything a running program does to the outside world goes through a Host: output, typed
// input, keys, the mouse and dialogs, the clock, waiting, and the hooks a live view or a tracer
// needs. rb's commands build a Host for the terminal, for headless runs and for tests; core/
// never touches stdin, stdout or the system clock itself.

#include <atomic>
#include <functional>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "input/input.h"
#include "robot/robot_link.h"
#include "base/runtime_error.h"
#include "base/source.h"

namespace rb {

class Machine;

/// Files and other programs a RobotBASIC program may reach (FileExists, FileRename, DirSet,
/// Spawn). Student programs are untrusted: rb's commands give an implementation that confines
/// files to the program's folder and refuses Spawn unless the user allows more
/// (run/sandbox.h). Failures are RuntimeErrors whose message names what was refused and why.
class SystemAccess {
 public:
  virtual ~SystemAccess() = default;
  virtual bool fileExists(std::string_view who, const std::string& path) = 0;
  virtual void renameFile(std::string_view who, const std::string& from, const std::string& to) = 0;
  /// Makes `path` the folder that later relative names start from.
  virtual void setDirectory(std::string_view who, const std::string& path) = 0;
  /// Runs a command line; `wait`: until it ends (returns its exit status), else returns at once
  /// (1 when it started). While it waits it calls `checkpoint` now and then: a run's limits
  /// hold during the wait, and when `checkpoint` throws, the command is ended and the exception
  /// goes on.
  virtual int64_t spawn(std::string_view who, const std::string& command, bool wait,
                        const std::function<void()>& checkpoint) = 0;
};

/// What a host's watchdog raises while a program runs (Host::armWatchdog), as bits of one
/// atomic so that the interpreter's check is a single load.
struct RunAlarms {
  static constexpr unsigned kDeadline = 1;  ///< the --timeout has passed
  static constexpr unsigned kMemory = 2;    ///< rb's memory went past --max-memory
  std::atomic<unsigned> raised{0};
  unsigned now() const { return raised.load(std::memory_order_relaxed); }
  void raise(unsigned bit) { raised.fetch_or(bit, std::memory_order_relaxed); }
};

/// The limits a watchdog keeps (0: none).
struct WatchdogLimits {
  double seconds = 0;
  uint64_t memoryBytes = 0;
};

class Host {
 public:
  virtual ~Host() = default;

  /// Called once the machine the host serves exists, before the program starts: a live view
  /// draws its screen, and input reaches its buttons and edit boxes.
  virtual void attachMachine(Machine& /*machine*/) {}

  /// Text the program prints (already formatted; "\n" ends lines).
  virtual void output(std::string_view text) = 0;
  /// One line typed in answer to `input` (without its line end); nullopt when input is over.
  virtual std::optional<std::string> inputLine(std::string_view prompt) = 0;
  /// Milliseconds since the run started, on the run's clock (virtual when headless).
  virtual double clockMs() = 0;
  /// Lets `ms` milliseconds pass on the run's clock (a headless run only advances its clock).
  virtual void wait(double ms) = 0;
  /// Seconds of real time since the run started, for --timeout.
  virtual double wallSeconds() = 0;
  /// Starts the host's watchdog (a thread of its own, say) for one run: it raises
  /// RunAlarms::kDeadline once `limits.seconds` of real time have passed since the run started
  /// and RunAlarms::kMemory when rb's memory goes past `limits.memoryBytes` (0: that limit is
  /// off), until disarmWatchdog(). The interpreter reads the alarms after every built-in call,
  /// in string and array growth and at its checkpoints, and long calls read them inside
  /// (Machine::checkAlarms), so both limits hold within one call's time even when single
  /// statements are slow. Without a watchdog (the default) the interpreter still compares
  /// wallSeconds() with the timeout every few thousand statements.
  virtual void armWatchdog(const WatchdogLimits& /*limits*/, RunAlarms& /*alarms*/) {}
  virtual void disarmWatchdog() {}
  /// Called regularly while the program runs; a live view redraws and reads keys here.
  /// Returning false stops the program (the user quit).
  virtual bool poll() { return true; }
  /// True once the host has asked the run to end (the user quit a live view). The interpreter
  /// stops as soon as the call in progress returns, with RunStatus::Stopped: what that call
  /// answered, and any runtime error it raised meanwhile, are not the program's doing and are
  /// dropped. This is how a host ends a run from inside a blocking call (waitKey, input, a
  /// delay): it requests the stop and returns at once, with any answer.
  bool stopRequested() const { return stopRequested_; }
  /// Called before each statement when the program was compiled for line tracing, while
  /// wantsLines() is true.
  virtual void onLine(SourceLoc /*loc*/) {}
  /// Whether onLine is called now. A host that needs the statements only at times (the web page:
  /// while the user steps) turns it off meanwhile, and each statement costs a test, not a call.
  bool wantsLines() const { return wantsLines_; }
  /// Called after each pixel or degree the robot moves, so a live view can animate it.
  virtual void animate() {}
  /// Milliseconds each pixel or degree of robot motion takes besides rSpeed's: 0 for a run that
  /// does not show the motion (a move at rSpeed 0 is then instantaneous); a live view gives the
  /// time RobotBASIC takes to draw a step, so that motion is visible at rSpeed 0 too.
  virtual double robotStepMs() const { return 0; }

  // ---- keyboard, mouse and dialogs (core/input/input.h). `who` names the built-in that asks, for
  // messages. The defaults are a run without keyboard or mouse: reads that do not block see
  // nothing, and waiting for input is a runtime error rather than a hang.

  /// The code of the key held down now (see keys::), 0 when none. Never blocks.
  virtual int64_t heldKey(std::string_view /*who*/) { return 0; }
  /// Waits until a key is down and returns its code; returns at once when one is held already.
  virtual int64_t waitKey(std::string_view who) { throw noInput(who, "a key"); }
  /// The mouse pointer (screen pixels) and buttons now. Never blocks.
  virtual MouseState mouse(std::string_view /*who*/) { return {}; }
  /// Waits until a mouse button goes down (a press not yet taken by an earlier waitClick
  /// counts); returns the mouse at that press.
  virtual MouseState waitClick(std::string_view who) { throw noInput(who, "a mouse click"); }
  /// Called before GetButton reads the program's controls: the host records button presses in
  /// `controls.pressed` (and may type into the edit boxes' text). Never blocks.
  virtual void updateControls(Controls& /*controls*/, std::string_view /*who*/) {}
  /// Shows a message box and waits until it is answered (OK).
  virtual void messageBox(std::string_view /*text*/, std::string_view /*title*/) {
    throw noInput("MsgBox", "an answer to the message box");
  }

  /// Files and processes; nullptr: this run reaches none (the built-ins say so).
  SystemAccess* system() const { return system_; }
  void setSystem(SystemAccess* s) { system_ = s; }
  /// SetCBtext: the run keeps the clipboard; a live view may also hand the text to the
  /// terminal's clipboard.
  virtual void clipboardChanged(std::string_view /*text*/) {}

  /// Memory the run's process holds now, in bytes (0 when the host cannot tell): a `dim` of a big
  /// array counts it against --max-memory before making the array.
  virtual uint64_t memoryInUse() { return 0; }

  /// `rCommPort port` with port != 0: opens the link to a real robot. Hosts without a serial
  /// driver refuse.
  virtual std::unique_ptr<RobotLink> openRobot(int64_t port) {
    throw RuntimeError("rCommPort " + std::to_string(port) +
                       ": no serial driver is available here; use the simulator (rCommPort 0)");
  }

 protected:
  /// Ends the run (see stopRequested); from now on blocking calls should return at once.
  void requestStop() { stopRequested_ = true; }
  /// See wantsLines().
  void setWantsLines(bool on) { wantsLines_ = on; }

  SystemAccess* system_ = nullptr;
  bool stopRequested_ = false;
  bool wantsLines_ = true;

  static RuntimeError noInput(std::string_view who, std::string_view what) {
    return RuntimeError(std::string(who) + ": cannot wait for " + std::string(what) +
                        ": this run has no keyboard or mouse");
  }
};

}  // namespace rb
