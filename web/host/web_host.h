#pragma once
// The Host of a run in a browser (or in node): rb's core compiled to WebAssembly with
// emscripten, JavaScript (web/rb.js, web/rblive.js) on the other side. The page's live runs
// go on in a Web Worker (web/rblive.js), never on the page's thread. There the host either
// waits synchronously for what the page sends (the rbcore_fast build: keys, clicks, Stop and
// Step through a SharedArrayBuffer and Atomics.wait, when the page is cross-origin isolated)
// or yields to the worker's event loop every few milliseconds (the rbcore build, emscripten's
// Asyncify: the page's messages arrive meanwhile). The host is the same code for both: only
// the waiting hooks are declared async in the Asyncify build.
//
// Two ways of running, chosen per run:
//   headless  what `rb run` does: a virtual clock that moves only when the program waits or
//             reads the clock, `input` lines from a given list (echoed, as from a pipe), keys,
//             clicks and message-box answers from scripted input (core/input/input_script.h).
//   live      the page's run: the real clock, `delay` waits, `input` is typed on the page, keys
//             and clicks come from the page, MsgBox is a page dialog; frames are shown as the
//             program draws.

#include <chrono>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "input/input_rules.h"
#include "input/input_script.h"
#include "machine/host.h"
#include "machine/interpreter.h"
#include "machine/machine.h"

namespace rb::web {

class WebHost : public Host {
 public:
  WebHost(bool live, std::vector<std::string> stdinLines, InputScript script);

  void attachMachine(Machine& machine) override;
  /// The running program, for the page's debugger: its variables and watches while paused.
  void attachInterpreter(const Interpreter& interpreter) { interpreter_ = &interpreter; }
  void output(std::string_view text) override;
  std::optional<std::string> inputLine(std::string_view prompt) override;
  double clockMs() override;
  void wait(double ms) override;
  double wallSeconds() override;
  bool poll() override;
  /// Before each statement of a live run: while the page steps, waits there for its Step.
  void onLine(SourceLoc loc) override;
  void animate() override;
  double robotStepMs() const override { return live_ ? stepMs_ : 0; }
  uint64_t memoryInUse() override;
  /// No thread: the limits are checked each time the run yields to the page (a slice).
  void armWatchdog(const WatchdogLimits& limits, RunAlarms& alarms) override;
  void disarmWatchdog() override;

  int64_t heldKey(std::string_view who) override;
  int64_t waitKey(std::string_view who) override;
  MouseState mouse(std::string_view who) override;
  MouseState waitClick(std::string_view who) override;
  void updateControls(Controls& controls, std::string_view who) override;
  void messageBox(std::string_view text, std::string_view title) override;
  /// `rCommPort n` on the page: a real robot over Web Serial (the page asks the user for the
  /// port), with the protocol and the messages of `rb run --real` (core/robot/reply_check.h).
  std::unique_ptr<RobotLink> openRobot(int64_t port) override;

  /// What the page's text alternative of the screen says, as JSON: the statement running, the
  /// robot's pose and pen, the last reading of each sensor the program read (most recent
  /// first) and the last line the program printed. Numbers as rb prints them (formatNumber),
  /// the pose to a tenth.
  std::string stateJson() const;
  /// Live runs: hands stateJson() to the page when it has changed, at most every
  /// kStateEveryMs unless `force` (a wait for the user, a step, the end).
  void presentState(bool force);
  static constexpr double kStateEveryMs = 250;

  /// The page's Stop: blocking calls return at once and the run ends at its next check.
  void stop() { requestStop(); }
  /// Gives the output gathered so far to the page.
  void flushOutput();
  /// Converts the screen, with the robot drawn on top as rb render draws it, to RGBA for the
  /// page's canvas and hands it over when it has changed; `force` false (while the program
  /// computes): only when the page has drawn the frames before.
  void present(bool force = true);
  /// The screen as `rb render -o OUT.svg` draws it, handed to the page. When the SVG must embed
  /// the screen's pixels (flip is on, a flood fill, ...), its <image> links to kScreenHref and the
  /// pixels (RGBA, without the robot) go with it: the page puts their PNG in that link's place.
  void presentSvg();
  /// A live run has ended: how (rb_run's JSON) goes to the page at once, before the SVG.
  void finished(const std::string& json);
  static constexpr const char* kScreenHref = "rb:screen.png";
  /// How long a robot on Web Serial has for each reply: rb run's --robot-timeout default.
  static constexpr double kRobotTimeoutSeconds = 2;
  /// Live runs: the program's buttons and edit boxes, and the edit box that has the keyboard,
  /// as JSON for the page, which shows them over the screen (they are not in its pixels);
  /// sent when they have changed.
  void presentControls();
  /// Milliseconds each pixel or degree of robot motion takes (the page's speed).
  double stepMs_ = 0;

 private:
  /// Lets the browser run (draw, take events) when enough time has passed since it last did;
  /// `force`: now.
  void yieldToPage(bool force);
  void checkLimits();
  /// After each visit to the page: a Stop, the speed and whether the page steps.
  void afterPage();
  /// Paused (the page's Pause or Step): shows the page `where` the run stands, the variables and
  /// the watches, and waits until the page resumes, steps or stops the run. `where`: "before"
  /// (the statement at `loc` is next), "move" (inside a robot motion) or "delay".
  void pauseAt(SourceLoc loc, const char* where);
  /// What the page's debugger shows while paused, as JSON.
  std::string debugJson(SourceLoc loc, const char* where);
  /// Inside a statement (a robot motion, a delay): pauses there when the page has asked to.
  void pauseInside();
  friend class WebSerialLink;
  /// The screen's pixels as RGBA in rgba_; false when there is no whole screen.
  bool toRgba(const Pixels& pixels);
  /// 0xRRGGBB as the little-endian word of RGBA bytes, opaque.
  static uint32_t rgbaWord(uint32_t rgb);

  bool live_;
  std::vector<std::string> stdin_;
  size_t nextLine_ = 0;
  double virtualMs_ = 0;
  ScriptedInput script_;
  InputRules rules_;
  Machine* machine_ = nullptr;
  std::string out_;
  std::vector<uint32_t> rgba_;  ///< RGBA, a pixel a word
  std::chrono::steady_clock::time_point start_;
  double lastYieldMs_ = 0;
  double lastFrameMs_ = -1000;
  bool stepping_ = false;   ///< the page asks to stop before each statement
  /// Stepped on from a pause inside a statement (a robot motion, a delay): the statement ends
  /// before the next pause.
  bool finishStatement_ = false;
  const Interpreter* interpreter_ = nullptr;
  double pausedSeconds_ = 0;  ///< time spent paused: the run's clock leaves it out
  double sleepDebtMs_ = 0;  ///< live: waiting the run owes, slept once it is worth a timer
  WatchdogLimits limits_;
  RunAlarms* alarms_ = nullptr;
  std::string controlsJson_;  ///< what the page was last shown of the controls
  std::string stateJson_;     ///< what the page was last given of the state
  double lastStateMs_ = -1000;
  std::string lineNow_;   ///< the line being printed (no line end yet)
  std::string lastLine_;  ///< the last line printed whole
  /// What the last frame showed: the screen's version and flips, the robot.
  struct Shown {
    uint64_t canvasVersion = 0, flips = 0;
    bool flip = false, robotVisible = false;
    double x = 0, y = 0, heading = 0, radius = 0;
    Colour colour = 0;
    bool operator==(const Shown&) const = default;
  };
  std::optional<Shown> lastShown_;
};

}  // namespace rb::web
