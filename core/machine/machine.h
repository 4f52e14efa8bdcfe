#pragma once
// The state a running program changes besides its variables: the host it talks to, the random
// generator, the screen and the robot. Built-in handlers receive the Machine; the interpreter
// owns none of this.

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "screen/canvas.h"
#include "machine/host.h"
#include "input/input.h"
#include "robot/real_robot.h"
#include "base/rng.h"
#include "robot/robot_sim.h"

namespace rb {

/// The most elements one array holds (dim, data, mFromString).
inline constexpr uint64_t kMaxArrayElements = 64u << 20;

/// Something the robot did, for `rb trace` and live views.
struct RobotEvent {
  enum Kind { Locate, Move, Turn, Pen, Crash, Sensor, Setting } kind;
  std::string_view command;   ///< the built-in's name, e.g. "rForward"
  SourceLoc loc;              ///< the statement that did it
  std::string args;           ///< its arguments as text ("120", "GREEN" as a number)
  Pose pose;                  ///< the robot's pose after the event
  bool pen = false;
  std::optional<double> value;  ///< a sensor's reading
};

/// What the program last read from one sensor built-in (rFeel, rRange, rBumper...).
struct SensorReading {
  std::string_view name;  ///< the built-in's name (the built-in table's own text)
  double value = 0;
  SourceLoc loc;          ///< the statement that read it
  uint64_t order = 0;     ///< the readings made when it was read: the latest has the most
};

class RobotObserver {
 public:
  virtual ~RobotObserver() = default;
  virtual void robotEvent(const RobotEvent& e) = 0;
};

class Machine {
 public:
  Machine(Host& host, uint64_t seed)
      : host_(host), rng_(seed), sim_(canvas_, rng_) {}
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  Host& host() { return host_; }
  /// What the host's watchdog has raised for this run (Host::armWatchdog).
  RunAlarms& alarms() { return alarms_; }
  bool alarmed() const { return alarms_.now() != 0; }
  /// For long loops inside a built-in, and growth of strings and arrays: ends the run when an
  /// alarm is up (DeadlinePassed for the timeout; a runtime error for memory).
  void checkAlarms() const {
    if (alarmed()) [[unlikely]] raiseAlarm();
  }
  /// Throws what the raised alarm means; the memory limit's message names the limit.
  [[noreturn]] void raiseAlarm() const;
  /// The --max-memory limit in bytes, for messages (0: none).
  uint64_t memoryLimit = 0;
  /// Whether `bytes` more fit in the --max-memory limit beside the memory the run holds already
  /// (always without a limit). What the run holds is asked of the host only for more than 64 KiB.
  bool memoryFits(uint64_t bytes);
  /// Before making something big (`dim`'s array, mFromString's fields): unless memoryFits, a
  /// runtime error saying that `what` would need `bytes`.
  void reserveMemory(uint64_t bytes, std::string_view what);
  /// The random generator; using it marks the run as depending on the seed.
  Rng& rng() {
    rngUsed_ = true;
    return rng_;
  }
  bool rngUsed() const { return rngUsed_ || sim_.slipPercent() > 0; }
  Canvas& canvas() { return canvas_; }
  const Canvas& canvas() const { return canvas_; }

  /// The robot the program's robot statements go to: the real robot while one is connected
  /// (rb's --real, rCommPort n), else the simulator. Traces, pictures and live views show this
  /// one.
  Robot& robot() { return real_ ? static_cast<Robot&>(*real_) : sim_; }
  const Robot& robot() const { return real_ ? static_cast<const Robot&>(*real_) : sim_; }
  /// The simulator, for what only it has (rSlip's error, the obstacle field).
  SimRobot& simulator() { return sim_; }
  /// The connected real robot, for what only it has (the port, what the link did), or nullptr.
  RealRobot* realRobot() { return real_.get(); }
  const RealRobot* realRobot() const { return real_.get(); }
  /// rCommPort n: opens port n through the host (n = 0: back to the simulator, closing it).
  void useCommPort(int64_t port);
  /// Sends robot commands to the real robot at the end of `link` from now on (rb's --real
  /// opens the link itself), closing any earlier one.
  void connectRobot(std::unique_ptr<RobotLink> link);

  /// The statement running now (the interpreter sets it before calling a built-in).
  SourceLoc location() const { return location_; }
  void setLocation(SourceLoc loc) { location_ = loc; }

  /// Notes what a sensor built-in read (each sensor's last reading is kept, for views that say
  /// it, as the web page's text of the screen does; no observer and no text needed). `sensor`
  /// is the built-in table's own name: the same text is always at the same address.
  void noteReading(std::string_view sensor, double value) {
    ++readings_;
    for (SensorReading& r : lastReadings_)
      if (r.name.data() == sensor.data()) {
        r.value = value, r.loc = location_, r.order = readings_;
        return;
      }
    lastReadings_.push_back({sensor, value, location_, readings_});
  }
  /// Each sensor's last reading, in the order the sensors were first read.
  const std::vector<SensorReading>& lastReadings() const { return lastReadings_; }

  void setObserver(RobotObserver* o) { observer_ = o; }
  bool observed() const { return observer_ != nullptr; }
  /// Reports a robot event to the observer, if any, filling in pose, pen and location.
  void emit(RobotEvent::Kind kind, std::string_view command, std::string args,
            std::optional<double> value = std::nullopt);

  /// `print`: writes the text to the host and onto the screen, then a line end unless
  /// `newline` is false.
  void print(std::string_view text, bool newline);
  /// `input`: shows the prompt and reads a line; a RuntimeError when input is over.
  std::string input(std::string_view prompt);
  /// `delay`: lets time pass on the run's clock.
  void delay(double ms);
  /// After each pixel or degree of robot motion: paces it at rSpeed (plus the host's drawing
  /// time, Host::robotStepMs) and lets a live view draw.
  void robotStepped();
  /// Whether robot motion goes a pixel or degree at a time (rSpeed paces it, or a live view
  /// shows it); otherwise a move is instantaneous.
  bool animatesRobot() const;
  /// waitKey's prompt: printed like `print` without a line end, except when the same prompt is
  /// still the last thing printed (a loop that waits for a held key would fill the screen).
  void printPrompt(std::string_view prompt);

  double robotSpeed = 0;  ///< rSpeed: milliseconds per pixel or degree

  // flip on/off: while on, what is shown of the screen (a live view, rb render's picture) is
  // the screen as it was at the last flip.
  bool flipMode = false;
  Pixels flipped;  ///< the screen at the last flip
  uint64_t flips = 0;  ///< how many times `flipped` was taken: a recording sees the shown screen change
  /// The screen's pixels as a viewer sees them: the last flip's while flip is on, else the
  /// canvas itself.
  const Pixels& shownScreen() const {
    return flipMode && !flipped.empty() ? flipped : canvas_.pixels();
  }
  /// True while what is shown is not the canvas (flip is on and the canvas changed since).
  bool showsFlip() const { return flipMode && !flipped.empty(); }

  /// AddButton, AddEdit: the program's dialog controls. Live views draw them; they are never
  /// drawn into the canvas, so the robot does not sense them.
  Controls controls;

  /// SetCBtext / GetCBtext: the clipboard belongs to the run (a live view may also copy it to
  /// the terminal's clipboard).
  std::string clipboard;

 private:
  Host& host_;
  RunAlarms alarms_;
  Rng rng_;
  bool rngUsed_ = false;
  Canvas canvas_;
  SimRobot sim_;
  std::unique_ptr<RealRobot> real_;
  SourceLoc location_;
  RobotObserver* observer_ = nullptr;
  std::vector<SensorReading> lastReadings_;
  uint64_t readings_ = 0;
  uint64_t prints_ = 0;           ///< print calls so far
  uint64_t promptPrintedAt_ = 0;  ///< prints_ right after printPrompt last printed
  std::string lastPrompt_;
};

}  // namespace rb
