#pragma once
// The Host of `rb run --tui`: the program runs in real time in a live ncurses view of the arena,
// with the source around the running line and the program's variables beside it. It paces
// delay, rSpeed and the robot's drawing on a run clock that stops while paused and runs faster or
// slower at the user's choice, pauses at single steps and breakpoints (tui_debugger.h), draws
// frames at a bounded rate from the interpreter's hooks, and turns terminal keys and mouse
// reports into what getKey, waitKey, readMouse, buttons, edit boxes and message boxes read (by
// the input rules every source of input follows, core/input/input_rules.h).
// docs/interaction.md describes it for users.

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "arena_view.h"
#include "curses_screen.h"
#include "file_watch.h"
#include "input/input_rules.h"
#include "machine/host.h"
#include "machine/interpreter.h"
#include "machine/machine.h"
#include "machine/recording.h"
#include "machine/watch.h"
#include "tui_debugger.h"
#include "tui_keyboard.h"
#include "tui_layout.h"
#include "tui_timeline.h"

namespace rb::tui {

/// A breakpoint as a restart keeps it: by the file's name (its index may change when the
/// program is loaded again) and line.
struct NamedBreakpoint {
  std::string file;
  uint32_t line = 0;
};

/// How the view starts: rb run's options for the first run, and for a restart what the view
/// was showing (TuiHost::nextSettings).
struct TuiSettings {
  std::string fileName;  ///< shown in the title
  render::CellMode mode = render::CellMode::Ascii;
  bool pixels = false;   ///< --cells pixels: the screen as an image where the terminal can show it
  double speed = 1;      ///< --speed
  bool paused = false;   ///< --paused: stop before the first statement
  bool watching = false;  ///< --watch: a save of the program restarts it
  std::vector<NamedBreakpoint> breakpoints;
  std::vector<std::string> watches;  ///< the watch expressions, in the order they were added
  int varScroll = 0;     ///< how far the variables pane is scrolled
  std::string notice;    ///< for the title at the start (why the run restarted, moved breakpoints)
};

class TuiHost : public Host, public RobotObserver {
 public:
  using Clock = std::chrono::steady_clock;

  /// Each pixel or degree of robot motion takes this long on the run clock besides rSpeed's: the
  /// time RobotBASIC takes to draw it on a PC, so that the seed's square (840 steps) takes about
  /// a second at rSpeed 0.
  static constexpr double kRobotStepMs = 1.2;
  /// Exit status when the user quits with Ctrl-C (as a shell reports a program ended by SIGINT).
  static constexpr int kInterruptedExit = 130;

  TuiHost(render::CursesScreen& screen, TuiSettings settings);

  /// The machine the view shows (the run sequence sets it before the run starts).
  void attachMachine(Machine& machine) override { machine_ = &machine; }
  /// The running program, for the source and variables panes and for stepping over calls.
  void watch(const Interpreter& interpreter, const SourceSet& sources) {
    interp_ = &interpreter;
    sources_ = &sources;
  }
  Debugger& debugger() { return debugger_; }
  /// The program's sources without a running program (its load failed): for the source pane.
  void showSources(const SourceSet* sources) { sources_ = sources; }
  /// Watched for saves of the program (--watch): a change restarts the run.
  FileWatch* fileWatch = nullptr;
  /// A notice for the title at the start of the run (a breakpoint that moved), shown for a
  /// few seconds.
  void startNotice(std::string text);

  void output(std::string_view text) override;
  std::optional<std::string> inputLine(std::string_view prompt) override;
  double clockMs() override;
  void wait(double ms) override;
  double wallSeconds() override;
  bool poll() override;
  void onLine(SourceLoc loc) override;
  void animate() override;
  double robotStepMs() const override { return kRobotStepMs; }
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

  /// After the run: shows how it ended (`error`: the runtime error's first line) and keeps the
  /// final frame until a key, unless the user quit or restarted.
  void showEnd(const RunResult& result, const std::string& error);
  /// Instead of a run, when the program could not be loaded (a syntax error saved with --watch,
  /// or found by a restart): shows `errors` (one per line) and waits for a restart (the key, or
  /// a save) or quitting.
  /// `at`: the first error's place, which the source pane shows.
  void showLoadErrors(const std::string& errors, SourceLoc at);
  /// The user asked for a restart (F12), or a watched file changed: the run ended at once and
  /// the caller runs the program again with nextSettings().
  bool restartRequested() const { return restart_; }
  /// The view as it is now, for the run after a restart: cell mode, speed, breakpoints by
  /// file name, the variables' scroll, and why it restarts.
  TuiSettings nextSettings() const;
  /// The exit status of a run the user quit: 0 for the quit keys, 130 for Ctrl-C.
  int quitCode() const { return quitCode_; }
  /// Everything the program printed (with the lines typed at `input` prompts), to be printed
  /// on the normal screen after the view closes, as a headless run would have printed it.
  const std::string& transcript() const { return transcript_; }
  /// True when the transcript reached its bound and later output was dropped.
  bool transcriptCut() const { return transcriptCut_; }

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
  /// one is due. A quit key requests the run's stop (Host::requestStop): every loop that waits
  /// here ends at once then, and the interpreter stops after the call in progress.
  void pump(int waitMs);
  /// pump(0), at most every few milliseconds: for hooks called very often.
  void tick();
  /// Pauses here (a step ended, or a breakpoint) and blocks until the user resumes or steps.
  void pauseHere();
  /// Blocks while paused.
  void holdWhilePaused();
  void handle(const render::TermEvent& e);
  void handleKey(int64_t key);
  void handleMouse(const render::TermEvent& e);
  /// rb's own keys; true when the key was one.
  bool viewKey(int64_t key);
  /// Keys that scroll the variables pane while paused or at the end; true when the key was one.
  bool scrollKey(int64_t key);
  /// Keys that move along the timeline while paused or at the end (Left, Right, Home, End; Esc
  /// back to the present); true when the key was one.
  bool timelineKey(int64_t key);
  /// Shows kept step `index` instead of the present (nullopt: the present again).
  void showStep(std::optional<size_t> index);
  /// How many kept steps lie before the present: the present is step number this (0-based)
  /// on the timeline.
  size_t stepsBeforePresent() const;
  /// The timeline is shown (paused, or at the end).
  bool timelineShown() const { return (paused_ || ended_) && !loadFailed_; }
  /// The statement shown: the one about to run, or the earlier step's.
  SourceLoc shownLoc() const;
  void setPaused(bool paused);
  void step(Debugger::Step kind);
  void toggleBreakpoint();
  void changeSpeed(double by);
  void cycleMode();
  /// F11: opens the line where a watch expression is typed.
  void openWatchPrompt();
  /// A key typed at that line: Enter adds the expression (or removes it when it is watched
  /// already), Esc closes the line.
  void watchPromptKey(int64_t key);
  void quit(int code);
  /// Ends the run (or the final screen) for a restart; `why` goes into the next run's title.
  void restart(std::string why);

  /// Blocks until `done` holds, showing `state`.
  void blockUntil(const char* state, const std::function<bool()>& done);
  void appendOutput(std::string_view text);
  /// The arena cells that show a button or an edit box (where a click hits it).
  Rect controlCells(int x, int y, int width, int height) const;
  /// Takes a new look at the program's variables (at each pause and step, and now and then
  /// while it runs).
  void refreshVariables();

  void draw();
  void drawArena();
  void drawOverlays();
  void drawStatus();
  void drawSource();
  void drawVariables();
  void drawOutput();
  /// The run state as the status panel shows it ("paused", "waiting for a key", "finished").
  std::string stateText() const;
  /// The same for the title, which also says why the run stopped ("paused at breakpoint, line 7").
  std::string titleState() const;
  ViewState viewState() const;

  render::CursesScreen& screen_;
  Machine* machine_ = nullptr;
  const Interpreter* interp_ = nullptr;
  const SourceSet* sources_ = nullptr;
  TuiSettings settings_;
  render::CellMode mode_;
  TuiLayout layout_;
  bool needLayout_ = true;
  bool layoutReal_ = false;  ///< the layout has room for a real robot's link rows
  bool redraw_ = false;  ///< Ctrl-L: draw every cell again

  RunClock clock_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point lastFrame_{};
  Clock::time_point lastTick_{};
  Clock::time_point lastVariables_{};
  double paceTarget_ = 0;  ///< where the last wait ended on the run clock
  uint32_t lineCount_ = 0;

  Debugger debugger_;
  bool paused_ = false;
  int quitCode_ = 0;
  bool restart_ = false;
  std::string restartWhy_;
  bool loadFailed_ = false;  ///< showLoadErrors: no program runs
  Clock::time_point lastWatch_{};
  bool ended_ = false;  ///< the run is over: the final screen is shown
  bool endKey_ = false;
  const char* waitingFor_ = nullptr;  ///< what a blocking read waits for, for the state line
  std::string endState_;
  std::string notice_;  ///< shown in the title while the run stays at noticeLoc_ ...
  SourceLoc noticeLoc_;
  Clock::time_point noticeUntil_{};  ///< ... or until then
  SourceLoc loc_;      ///< the statement running now (or about to, when paused)
  SourceLoc errorLoc_;  ///< where the run's error (or the first load error) is, once ended
  SourceLoc breakAt_;  ///< where a breakpoint paused the run (invalid: not paused by one)
  size_t depth_ = 0;   ///< its gosub/call depth

  // Keyboard.
  bool programKeys_ = false;  ///< the program reads the keyboard: single-key shortcuts are off
  HeldKeys held_;
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

  // What the program printed: the pane's lines, and all of it for after the view closes.
  std::deque<std::string> lines_;
  std::string partial_;
  std::string transcript_;
  bool transcriptCut_ = false;

  // The timeline: the run's recording, fed from the hooks; the earlier step shown instead of
  // the present, if any, with its screen decoded once.
  Recording recording_{kTimelineBudget};
  std::optional<size_t> past_;
  std::optional<PastStep> pastShown_;
  size_t pastShownIndex_ = 0;
  bool atStatement_ = false;  ///< paused in onLine: the present is that statement's kept step
  int barCol_ = 0, barWidth_ = 0;  ///< where the position bar is on the screen (output header)

  // Watch expressions (machine/watch.h), and the line one is typed at.
  std::vector<Watch> watches_;
  bool prompting_ = false;
  std::string promptText_;

  // The variables pane: its lines at the last look, and how far it is scrolled.
  std::vector<std::string> varLines_;
  int varScroll_ = 0;

  std::optional<double> lastRange_;
  std::string error_;

  // The arena frame, drawn again only when something it shows changed.
  render::ArenaFrame frame_;
  uint64_t frameCanvasVersion_ = 0;
  render::RobotView frameRobot_;
  render::CellMode frameMode_ = render::CellMode::Ascii;
  size_t frameTextOps_ = 0;
  int64_t frameStep_ = -1;  ///< the kept step frame_ shows (-1: the present)
  // --cells pixels: the arena as a sixel image.
  bool pixels_ = false;
  bool sixelSent_ = false;  ///< the image of frame_ is on the terminal
  std::string pixelsNote_;  ///< why --cells pixels shows characters instead
};

}  // namespace rb::tui
