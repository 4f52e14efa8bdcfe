#pragma once
// The Host of `rb run --tui`: the program runs in real time in a live ncurses view of the arena.
// It paces delay and rSpeed on a run clock that stops while paused and runs faster or slower at
// the user's choice, draws frames at a bounded rate from the interpreter's hooks, and turns
// terminal keys and mouse reports into what getKey, waitKey, readMouse, buttons, edit boxes and
// message boxes read. docs/interaction.md describes it for users.

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "arena_view.h"
#include "curses_screen.h"
#include "input/input_rules.h"
#include "machine/host.h"
#include "machine/interpreter.h"
#include "machine/machine.h"
#include "tui_layout.h"

namespace rb::cli {

class TuiHost : public Host, public RobotObserver {
 public:
  using Clock = std::chrono::steady_clock;

  TuiHost(render::CursesScreen& screen, std::string fileName, render::CellMode mode);

  /// The machine the view shows (the run sequence sets it before the run starts).
  void attachMachine(Machine& machine) override { machine_ = &machine; }

  void output(std::string_view text) override;
  std::optional<std::string> inputLine(std::string_view prompt) override;
  double clockMs() override;
  void wait(double ms) override;
  double wallSeconds() override;
  bool poll() override;
  void onLine(SourceLoc loc) override;
  void animate() override;
  int64_t heldKey(std::string_view who) override;
  int64_t waitKey(std::string_view who) override;
  MouseState mouse(std::string_view who) override;
  MouseState waitClick(std::string_view who) override;
  void updateControls(Controls& controls, std::string_view who) override;
  void messageBox(std::string_view text, std::string_view title) override;
  /// SetCBtext: also hands the text to the terminal's clipboard (OSC 52; terminals that do not
  /// support it ignore the sequence).
  void clipboardChanged(std::string_view text) override;
  std::unique_ptr<RobotLink> openRobot(int64_t port) override {
    if (robotOpener) return robotOpener(port);
    return Host::openRobot(port);
  }
  void robotEvent(const RobotEvent& e) override;

  /// After the run: shows how it ended (`error`: the runtime error's first line) and waits for a
  /// key, unless the user quit.
  void showEnd(const RunResult& result, const std::string& error);

  /// Opens a real robot's port for rCommPort.
  std::function<std::unique_ptr<RobotLink>(int64_t)> robotOpener;

 private:
  /// The program's clock: real time scaled by the speed factor, stopped while paused.
  class RunClock {
   public:
    double now() const;
    void setRunning(bool running);
    void setFactor(double factor);
    double factor() const { return factor_; }

   private:
    double base_ = 0;
    Clock::time_point anchor_ = Clock::now();
    double factor_ = 1;
    bool running_ = true;
  };

  /// Reads the terminal (waiting up to `waitMs` for the first event) and draws a frame when
  /// one is due. Throws StopRun when the user quit.
  void pump(int waitMs);
  /// pump(0), at most every few milliseconds: for hooks called very often.
  void tick();
  /// Blocks while paused (after a single step, too).
  void holdWhilePaused();
  void handle(const render::TermEvent& e);
  void handleKey(int64_t key);
  void handleMouse(const render::TermEvent& e);
  /// rb's own keys; true when the key was one.
  bool viewKey(int64_t key);
  void setPaused(bool paused);
  void step();
  void changeSpeed(double by);
  void cycleMode();
  /// The key getKey sees now (held keys are inferred: terminals report presses only).
  int64_t currentKey();

  /// Blocks until `done` holds, showing `state`.
  void blockUntil(const char* state, const std::function<bool()>& done);
  void appendOutput(std::string_view text);
  /// The arena cells that show a button or an edit box (where a click hits it).
  Rect controlCells(int x, int y, int width, int height) const;

  void draw();
  void drawArena();
  void drawOverlays();
  void drawStatus();
  void drawOutput();
  std::string stateText() const;

  render::CursesScreen& screen_;
  Machine* machine_ = nullptr;
  std::string file_;
  render::CellMode mode_;
  TuiLayout layout_;
  bool needLayout_ = true;

  RunClock clock_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastFrame_{};
  Clock::time_point lastTick_{};
  double paceTarget_ = 0;  ///< where the last wait ended on the run clock
  uint32_t lineCount_ = 0;

  bool paused_ = false;
  bool stepArmed_ = false;  ///< pause again at the next statement or robot step
  bool quit_ = false;
  bool ended_ = false;  ///< the run is over: the final screen is shown
  bool endKey_ = false;
  const char* waitingFor_ = nullptr;  ///< what a blocking read waits for, for the state line
  std::string endState_;

  // Keyboard: the last key pressed and whether a read has seen it.
  bool programKeys_ = false;
  int64_t key_ = 0;
  Clock::time_point keyAt_{};
  bool keySeen_ = false;
  std::deque<int64_t> typed_;  ///< presses not yet taken by waitKey (typing ahead)

  // Mouse, in screen pixels; presses stay visible until a read has seen them.
  MouseState mouse_;
  int latched_ = 0;
  std::deque<MouseState> clicks_;  ///< presses not yet taken by waitClick
  InputRules rules_;               ///< which edit box has the keyboard

  // Dialogs.
  struct Box {
    std::string title, text;
  };
  std::optional<Box> box_;
  bool boxAnswered_ = false;
  bool inputActive_ = false;
  bool inputDone_ = false;
  bool inputEof_ = false;
  std::string inputPrompt_, inputText_;

  // What the program printed.
  std::deque<std::string> lines_;
  std::string partial_;

  SourceLoc loc_;
  std::optional<double> lastRange_;
  std::string error_;

  // The arena frame, drawn again only when something it shows changed.
  render::ArenaFrame frame_;
  uint64_t frameCanvasVersion_ = 0;
  render::RobotView frameRobot_;
  render::CellMode frameMode_ = render::CellMode::Ascii;
};

}  // namespace rb::cli
