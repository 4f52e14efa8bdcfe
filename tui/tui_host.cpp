#include "tui_host.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "png_writer.h"
#include "robot/protocol.h"
#include "robot_view.h"
#include "sixel_image.h"
#include "svg_writer.h"
#include "tui_panes.h"

namespace rb::tui {

namespace {

using render::TermEvent;
using render::TermStyle;

constexpr auto kFrameInterval = std::chrono::milliseconds(33);  // at most ~30 frames a second
constexpr auto kTickInterval = std::chrono::milliseconds(8);    // how often hot hooks read keys
/// How often the variables pane takes a new look while the program runs.
constexpr auto kVariablesInterval = std::chrono::milliseconds(250);
/// Waits that start within this many run-clock milliseconds of the previous one's end continue
/// its schedule, so the time between waits does not slow the animation down.
constexpr double kPaceSlackMs = 50;
constexpr size_t kMaxOutputLines = 1000;
/// What the transcript keeps at most (printed after the view closes); later output is dropped.
constexpr size_t kMaxTranscript = 64u << 20;
constexpr size_t kMaxTypedAhead = 8;
constexpr double kMinFactor = 1.0 / 64, kMaxFactor = 64;
/// How often the view asks the file watch (--watch) whether the program was saved.
constexpr auto kWatchInterval = std::chrono::milliseconds(100);

// Control characters of the keys rb keeps (raw mode delivers them as keys). None is a common
// prefix of tmux (Ctrl-B) or screen (Ctrl-A).
constexpr int64_t kCtrlC = 3, kCtrlE = 5, kCtrlF = 6, kCtrlG = 7, kCtrlL = 12, kCtrlN = 14,
                  kCtrlP = 16, kCtrlQ = 17, kCtrlR = 18, kCtrlS = 19, kCtrlT = 20, kCtrlV = 22,
                  kCtrlW = 23;

int64_t fKey(int n) { return keys::kF1 + n - 1; }

const char* modeName(render::CellMode m) {
  switch (m) {
    case render::CellMode::Ascii: return "ascii";
    case render::CellMode::HalfBlock: return "half";
    case render::CellMode::Braille: return "braille";
  }
  return "?";
}

bool sameRobot(const render::RobotView& a, const render::RobotView& b) {
  return a.visible == b.visible && a.x == b.x && a.y == b.y && a.heading == b.heading &&
         a.radius == b.radius && a.colour == b.colour;
}

/// Resets a pointer-to-state when a blocking read ends, also by an exception (the user quit).
class Waiting {
 public:
  Waiting(const char*& slot, const char* what) : slot_(slot) { slot_ = what; }
  ~Waiting() { slot_ = nullptr; }
  Waiting(const Waiting&) = delete;
  Waiting& operator=(const Waiting&) = delete;

 private:
  const char*& slot_;
};

}  // namespace

// ---- the run clock

double TuiHost::RunClock::now() const {
  if (!running_) return base_;
  return base_ +
         std::chrono::duration<double, std::milli>(Clock::now() - anchor_).count() * factor_;
}

void TuiHost::RunClock::setRunning(bool running) {
  if (running == running_) return;
  base_ = now();
  anchor_ = Clock::now();
  running_ = running;
}

void TuiHost::RunClock::setFactor(double factor) {
  base_ = now();
  anchor_ = Clock::now();
  factor_ = factor;
}

// ---- Host

TuiHost::TuiHost(render::CursesScreen& screen, TuiSettings settings)
    : screen_(screen), settings_(std::move(settings)), mode_(settings_.mode) {
  clock_.setFactor(std::clamp(settings_.speed, kMinFactor, kMaxFactor));
  held_.setReportsReleases(screen_.reportsKeyReleases());
  pixels_ = settings_.pixels && screen_.sixel();
  if (settings_.pixels && !pixels_) pixelsNote_ = "(no pixels: the terminal shows no sixel images)";
  // --paused: a step armed from the start ends before the first statement.
  if (settings_.paused) debugger_.step(Debugger::Step::Into, 0);
  varScroll_ = settings_.varScroll;
  for (const std::string& w : settings_.watches) watches_.emplace_back(w);
  if (!settings_.notice.empty()) startNotice(settings_.notice);
}

void TuiHost::output(std::string_view text) { appendOutput(text); }

void TuiHost::appendOutput(std::string_view text) {
  recording_.output(text);
  if (transcript_.size() + text.size() <= kMaxTranscript) transcript_ += text;
  else transcriptCut_ = true;
  for (char c : text) {
    if (c == '\n') {
      lines_.push_back(std::move(partial_));
      partial_.clear();
      if (lines_.size() > kMaxOutputLines) lines_.pop_front();
    } else {
      partial_ += c;
    }
  }
}

double TuiHost::clockMs() { return clock_.now(); }

double TuiHost::wallSeconds() {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void TuiHost::wait(double ms) {
  double now = clock_.now();
  double target = now - paceTarget_ <= kPaceSlackMs ? paceTarget_ + ms : now + ms;
  paceTarget_ = target;
  for (;;) {
    double left = target - clock_.now();
    if (left <= 0 || stopRequested()) break;
    if (paused_) {
      pump(50);
      continue;
    }
    // Reading the terminal with a timeout is the sleep, so keys work during long delays.
    pump(static_cast<int>(std::min(left / clock_.factor(), 20.0)));
  }
}

bool TuiHost::poll() {
  pump(0);
  return !stopRequested();
}

void TuiHost::onLine(SourceLoc loc) {
  loc_ = loc;
  depth_ = interp_ ? interp_->callDepth() : 0;
  if (machine_) recording_.statement(loc, *machine_);
  if (debugger_.pauseAtStatement(loc, depth_)) {
    breakAt_ = debugger_.stoppedAtBreakpoint() ? loc : SourceLoc{};
    atStatement_ = true;
    pauseHere();
    atStatement_ = false;
    return;
  }
  if (paused_) {
    atStatement_ = true;
    holdWhilePaused();
    atStatement_ = false;
    return;
  }
  if ((++lineCount_ & 255) == 0) tick();
}

void TuiHost::animate() {
  if (debugger_.pauseAtRobotStep()) {
    pauseHere();
    return;
  }
  if (paused_) {
    holdWhilePaused();
    return;
  }
  tick();
}

void TuiHost::pauseHere() {
  setPaused(true);
  holdWhilePaused();
}

void TuiHost::holdWhilePaused() {
  if (!paused_) return;
  refreshVariables();
  draw();
  while (paused_ && debugger_.armed() == Debugger::Step::None && !stopRequested()) pump(50);
}

void TuiHost::tick() {
  if (Clock::now() - lastTick_ >= kTickInterval) pump(0);
}

void TuiHost::pump(int waitMs) {
  TermEvent e = screen_.read(waitMs);
  // A bound per call, so that a flood of mouse reports cannot starve the program.
  for (int budget = 64; e.kind != TermEvent::None && budget > 0; --budget) {
    handle(e);
    e = screen_.read(0);
  }
  if (e.kind != TermEvent::None) handle(e);
  lastTick_ = Clock::now();
  if (fileWatch && !restart_ && lastTick_ - lastWatch_ >= kWatchInterval) {
    lastWatch_ = lastTick_;
    if (fileWatch->changed()) restart("restarted: " + settings_.fileName + " was saved");
  }
  if (lastTick_ - lastFrame_ >= kFrameInterval) draw();
}

void TuiHost::blockUntil(const char* state, const std::function<bool()>& done) {
  if (!paused_ && done()) {
    tick();
    return;
  }
  Waiting waiting(waitingFor_, state);
  draw();
  // Paused, the program takes nothing: what arrives waits until the view resumes.
  while (!stopRequested() && (paused_ || !done())) pump(20);
}

int64_t TuiHost::heldKey(std::string_view) {
  programKeys_ = true;
  tick();
  // A program that polls sees presses here: a later waitKey must not get them again.
  typed_.clear();
  return held_.read(Clock::now());
}

int64_t TuiHost::waitKey(std::string_view) {
  programKeys_ = true;
  // Each press (or auto-repeat of a held key) answers one waitKey, in the order typed.
  blockUntil("waiting for a key", [this] { return !typed_.empty(); });
  if (typed_.empty()) return 0;  // the user quit
  int64_t key = typed_.front();
  typed_.pop_front();
  return key;
}

MouseState TuiHost::mouse(std::string_view) {
  tick();
  MouseState s = mouse_;
  s.buttons |= latched_;
  latched_ = 0;
  clicks_.clear();  // seen here: a later waitClick must not get them again
  return s;
}

MouseState TuiHost::waitClick(std::string_view) {
  blockUntil("waiting for a click", [this] { return !clicks_.empty(); });
  if (clicks_.empty()) return {};  // the user quit
  MouseState click = clicks_.front();
  clicks_.pop_front();
  latched_ = 0;
  return click;
}

void TuiHost::updateControls(Controls&, std::string_view) {
  tick();  // a click on a button presses it at once (InputRules::press)
}

void TuiHost::clipboardChanged(std::string_view text) {
  std::string seq = "\033]52;c;" + render::base64Encode({text.begin(), text.end()}) + "\a";
  std::fwrite(seq.data(), 1, seq.size(), stdout);
  std::fflush(stdout);
}

void TuiHost::messageBox(std::string_view text, std::string_view title) {
  box_ = Box{std::string(title), std::string(text)};
  boxAnswered_ = false;
  blockUntil("message box", [this] { return boxAnswered_; });
  box_.reset();
}

std::optional<std::string> TuiHost::inputLine(std::string_view prompt) {
  programKeys_ = true;
  inputActive_ = true;
  inputDone_ = inputEof_ = false;
  inputPrompt_ = prompt;
  inputText_.clear();
  blockUntil("input", [this] { return inputDone_; });
  inputActive_ = false;
  if (stopRequested()) return std::nullopt;  // the user quit
  appendOutput(inputPrompt_ + inputText_ + "\n");
  if (inputEof_) return std::nullopt;
  recording_.input(inputText_);
  return inputText_;
}

void TuiHost::robotEvent(const RobotEvent& e) {
  recording_.robotEvent(e);
  if (e.kind == RobotEvent::Sensor && e.command == "rRange" && e.value) lastRange_ = *e.value;
}

void TuiHost::showEnd(const RunResult& result, const std::string& error) {
  if (result.status == RunStatus::Stopped) return;
  ended_ = true;
  paused_ = false;
  debugger_.cancelStep();
  clock_.setRunning(false);
  box_.reset();
  inputActive_ = false;
  error_ = error;
  if (result.error) errorLoc_ = result.error->loc;
  if (machine_) recording_.finish(*machine_, result);
  switch (result.status) {
    case RunStatus::Finished: endState_ = "finished"; break;
    case RunStatus::RuntimeError: endState_ = "error"; break;
    default: endState_ = "stopped (limit)"; break;
  }
  refreshVariables();
  blockUntil("", [this] { return endKey_; });  // quitting ends the final screen too
}

void TuiHost::showLoadErrors(const std::string& errors, SourceLoc at) {
  loadFailed_ = true;
  loc_ = at;
  ended_ = true;  // nothing runs: no pause, step or breakpoint
  clock_.setRunning(false);
  endState_ = "not loaded";
  error_ = errors;
  errorLoc_ = at;
  // Only a restart (F12, or a save with --watch) or quitting ends this: there is no final
  // screen to leave with any key.
  blockUntil("", [this] { return endKey_; });
}

TuiSettings TuiHost::nextSettings() const {
  TuiSettings next = settings_;
  next.mode = mode_;
  // Pixels asked for on a terminal without them stay asked for, so the title still says why.
  next.pixels = pixels_ || (settings_.pixels && !screen_.sixel());
  next.speed = clock_.factor();
  next.varScroll = varScroll_;
  next.notice = restartWhy_;
  next.watches.clear();
  for (const Watch& w : watches_) next.watches.push_back(w.text());
  if (!loadFailed_ && sources_) {
    next.breakpoints.clear();
    for (auto [file, line] : debugger_.breakpoints())
      if (file < sources_->size()) next.breakpoints.push_back({sources_->file(file).name(), line});
  }
  return next;
}

void TuiHost::refreshVariables() {
  lastVariables_ = Clock::now();
  int width = layout_.vars.width;
  if (width <= 0) return;
  std::vector<VariableView> vars;
  if (interp_) vars = interp_->variables();
  std::vector<WatchLine> shown;
  for (const Watch& w : watches_) {
    WatchLine line;
    line.expr = w.text();
    if (!interp_ || !machine_) {
      line.value = "no program runs";
      line.error = true;
    } else if (WatchResult r = w.evaluate(vars, *machine_); r.value) {
      line.value = valueText(*r.value, static_cast<size_t>(width));
    } else {
      line.value = r.error;
      line.error = true;
    }
    shown.push_back(std::move(line));
  }
  varLines_ = watchLines(shown, width);
  if (interp_) {
    std::vector<std::string> lines = variableLines(vars, interp_->runningSub(), width);
    varLines_.insert(varLines_.end(), lines.begin(), lines.end());
  }
}

// ---- keys and the mouse

void TuiHost::handle(const TermEvent& e) {
  switch (e.kind) {
    case TermEvent::Resize:
      needLayout_ = true;
      sixelSent_ = false;
      lastFrame_ = {};  // draw at once
      break;
    case TermEvent::Key:
      if (e.release) held_.release(e.key, Clock::now());
      else handleKey(e.key);
      break;
    case TermEvent::Mouse: handleMouse(e); break;
    case TermEvent::None: break;
  }
}

bool TuiHost::viewKey(int64_t key) {
  if (key == fKey(2) || key == kCtrlP) setPaused(!paused_);
  else if (key == fKey(3) || key == kCtrlS) step(Debugger::Step::Into);
  else if (key == fKey(7) || key == kCtrlN) step(Debugger::Step::Over);
  else if (key == fKey(8) || key == kCtrlR) step(Debugger::Step::Robot);
  else if (key == fKey(9) || key == kCtrlT) toggleBreakpoint();
  else if (key == fKey(4) || key == kCtrlW) changeSpeed(0.5);
  else if (key == fKey(5) || key == kCtrlF) changeSpeed(2);
  else if (key == fKey(6) || key == kCtrlV) cycleMode();
  else if (key == kCtrlL) redraw_ = true;
  else if (key == fKey(12) || key == kCtrlG) restart("restarted");
  else if (key == fKey(11) || key == kCtrlE) openWatchPrompt();
  else if (key == fKey(10) || key == kCtrlQ) quit(0);
  else if (key == kCtrlC) quit(kInterruptedExit);
  else return false;
  lastFrame_ = {};  // show the change at once
  return true;
}

size_t TuiHost::stepsBeforePresent() const {
  const std::vector<RecordedStep>& steps = recording_.steps();
  if (steps.empty()) return 0;
  // The present is the last kept step when the run stands exactly there: at the end (the
  // recording's last step), or paused before a statement that was kept. Paused inside a
  // statement (a pixel step, a delay, a wait for a key) the present is past its start.
  bool there = ended_ ? recording_.finished()
                      : atStatement_ && steps.back().step + 1 == recording_.totalSteps();
  return there ? steps.size() - 1 : steps.size();
}

void TuiHost::showStep(std::optional<size_t> index) {
  past_ = index;
  if (past_ && (!pastShown_ || pastShownIndex_ != *past_)) {
    pastShown_ = pastStep(recording_, *past_);
    pastShownIndex_ = *past_;
  }
  if (!past_) pastShown_.reset();
  lastFrame_ = {};
}

SourceLoc TuiHost::shownLoc() const {
  if (past_ && pastShown_ && pastShown_->step.loc.valid()) return pastShown_->step.loc;
  return loc_;
}

bool TuiHost::timelineKey(int64_t key) {
  if (!timelineShown()) return false;
  size_t present = stepsBeforePresent();
  const std::vector<RecordedStep>& steps = recording_.steps();
  if (key == keys::kLeft) {
    if (past_) showStep(*past_ > 0 ? *past_ - 1 : 0);
    else if (present > 0) showStep(present - 1);
  } else if (key == keys::kRight) {
    // Forward past the last kept step is the present again; the run goes on only by F2 or a
    // step (looking back is looking).
    if (past_) showStep(*past_ + 1 < present ? std::optional<size_t>(*past_ + 1) : std::nullopt);
  } else if (key == keys::kHome) {
    if (present == 0) return true;
    size_t from = past_ ? *past_ : std::min(present, steps.size() - 1);
    size_t to = jumpFrom(recording_, from, -0.1);
    showStep(std::min(to, present - 1));
  } else if (key == keys::kEnd) {
    if (!past_) return true;
    size_t to = jumpFrom(recording_, *past_, 0.1);
    showStep(to < present && to > *past_ ? std::optional<size_t>(to) : std::nullopt);
  } else if (key == keys::kEsc && past_) {
    showStep(std::nullopt);
  } else {
    return false;
  }
  return true;
}

bool TuiHost::scrollKey(int64_t key) {
  int page = std::max(layout_.vars.height - 1, 1);
  int by = key == keys::kUp ? -1 : key == keys::kDown ? 1 : key == keys::kPageUp ? -page
         : key == keys::kPageDown ? page : 0;
  if (by == 0) return false;
  int most = std::max(static_cast<int>(varLines_.size()) - layout_.vars.height, 0);
  varScroll_ = std::clamp(varScroll_ + by, 0, most);
  lastFrame_ = {};
  return true;
}

void TuiHost::handleKey(int64_t key) {
  if (viewKey(key)) return;
  if (prompting_) {
    watchPromptKey(key);
    return;
  }
  if (loadFailed_) return;  // nothing to exit to but quitting
  if (timelineKey(key)) return;
  if (ended_) {
    if (!scrollKey(key)) endKey_ = true;
    return;
  }
  // Paused, the arrows and page keys scroll the variables pane; the rest wait for the program.
  if (paused_ && scrollKey(key)) return;
  if (box_) {
    if (InputRules::answersMessageBox(key)) boxAnswered_ = true;
    return;
  }
  if (inputActive_) {
    switch (InputRules::editLine(inputText_, key)) {
      case InputRules::LineKey::Done: inputDone_ = true; break;
      case InputRules::LineKey::EndOfInput: inputDone_ = inputEof_ = true; break;
      default: break;
    }
    lastFrame_ = {};
    return;
  }
  if (machine_ && rules_.typeInto(machine_->controls, key)) {
    lastFrame_ = {};
    return;
  }
  if (!programKeys_) {
    // Until the program reads the keyboard, single keys control the view too.
    switch (key) {
      case 'p':
      case ' ': setPaused(!paused_); lastFrame_ = {}; return;
      case 's': step(Debugger::Step::Into); return;
      case 'n': step(Debugger::Step::Over); return;
      case 'r': step(Debugger::Step::Robot); return;
      case 'b': toggleBreakpoint(); return;
      case '-': changeSpeed(0.5); return;
      case '+':
      case '=': changeSpeed(2); return;
      case 'v': cycleMode(); return;
      case 'g': restart("restarted"); return;
      case 'w': openWatchPrompt(); return;
      case 'q': quit(0); return;
      default: break;
    }
  }
  held_.press(key, Clock::now());
  typed_.push_back(key);
  // Bounded, so that the auto-repeat of a key held while the program is busy does not run on
  // long after the key is let go.
  if (typed_.size() > kMaxTypedAhead) typed_.pop_front();
}

void TuiHost::handleMouse(const TermEvent& e) {
  if (layout_.tooSmall || layout_.arena.width == 0) return;
  if (e.pressed && timelineShown() && barWidth_ > 0 && e.row == layout_.output.row &&
      e.col >= barCol_ && e.col < barCol_ + barWidth_) {
    // A click on the position bar shows the step at that place (its end: the present).
    size_t present = stepsBeforePresent();
    size_t at = stepAtColumn(e.col, barCol_, barWidth_, present + 1);
    showStep(at < present ? std::optional<size_t>(at) : std::nullopt);
    return;
  }
  bool inArena = layout_.arena.contains(e.col, e.row);
  auto [x, y] = cellToPixel(layout_.arena, e.col, e.row);
  if (box_) {
    if (InputRules::clickAnswersMessageBox(e.pressed)) boxAnswered_ = true;
    return;
  }
  if (e.pressed && inArena && machine_ && !ended_) {
    // A press goes to the button or edit box that the cell shows part of, if any.
    Rect p = cellPixels(layout_.arena, e.col, e.row);
    if (rules_.press(machine_->controls, p.col, p.row, p.width, p.height) !=
        InputRules::Target::Program) {
      lastFrame_ = {};
      return;
    }
  }
  // Outside the arena the pointer stays at the nearest edge while a drag goes on.
  if (inArena || mouse_.buttons) {
    mouse_.x = x;
    mouse_.y = y;
  }
  if (inArena && e.pressed) {
    mouse_.buttons |= e.pressed;
    latched_ |= e.pressed;
    clicks_.push_back(mouse_);
    if (clicks_.size() > kMaxTypedAhead) clicks_.pop_front();
  }
  mouse_.buttons &= ~e.released;
}

Rect TuiHost::controlCells(int x, int y, int width, int height) const {
  return cellsShowing(layout_.arena, x, y, width, height);
}

void TuiHost::setPaused(bool paused) {
  if (ended_) return;
  paused_ = paused;
  if (!paused) {
    debugger_.cancelStep();
    breakAt_ = {};
    showStep(std::nullopt);  // the run goes on from the present
  } else {
    held_.clear();  // keys held when the view paused are let go
    // The variables as they are now: running, the pane is refreshed only now and then, and a
    // pause inside a robot motion or a delay waits there, not at a statement.
    refreshVariables();
  }
  clock_.setRunning(!paused);
}

void TuiHost::step(Debugger::Step kind) {
  if (ended_) return;
  // Paused: run to the step's end, then pause again. Running: pause at the step's end.
  debugger_.step(kind, depth_);
  paused_ = false;
  breakAt_ = {};
  showStep(std::nullopt);
  clock_.setRunning(true);
}

void TuiHost::toggleBreakpoint() {
  // On the line shown: the running line, or an earlier step's (also after the end).
  SourceLoc at = shownLoc();
  if ((ended_ && !past_) || !at.valid()) return;
  bool set = debugger_.toggleBreakpoint(at.file, at.line);
  // The shown line's marker is '>' either way: the title says what happened.
  notice_ = (set ? "breakpoint set on line " : "breakpoint cleared on line ") +
            std::to_string(at.line);
  noticeLoc_ = loc_;
  noticeUntil_ = Clock::now() + std::chrono::seconds(3);
}

void TuiHost::startNotice(std::string text) {
  constexpr auto kStartNotice = std::chrono::seconds(5);
  notice_ = std::move(text);
  noticeLoc_ = {};
  noticeUntil_ = Clock::now() + kStartNotice;
}

void TuiHost::openWatchPrompt() {
  prompting_ = true;
  promptText_.clear();
}

void TuiHost::watchPromptKey(int64_t key) {
  lastFrame_ = {};
  if (key == keys::kEsc) {
    prompting_ = false;
    return;
  }
  if (InputRules::editLine(promptText_, key) != InputRules::LineKey::Done) return;
  prompting_ = false;
  std::string text = promptText_;
  while (!text.empty() && text.back() == ' ') text.pop_back();
  text.erase(0, text.find_first_not_of(' '));
  if (text.empty()) return;
  // The same expression again takes it away: one key adds and removes, as F9 does breakpoints.
  auto same = std::find_if(watches_.begin(), watches_.end(),
                           [&](const Watch& w) { return w.text() == text; });
  if (same != watches_.end()) {
    watches_.erase(same);
    startNotice("watch removed: " + text);
  } else {
    watches_.emplace_back(text);
  }
  refreshVariables();
}

void TuiHost::changeSpeed(double by) {
  clock_.setFactor(std::clamp(clock_.factor() * by, kMinFactor, kMaxFactor));
}

void TuiHost::quit(int code) {
  quitCode_ = code;
  requestStop();
}

void TuiHost::restart(std::string why) {
  restart_ = true;
  restartWhy_ = std::move(why);
  endKey_ = true;  // leaves the final screen too
  requestStop();
}

void TuiHost::cycleMode() {
  using render::CellMode;
  // The character modes the terminal can show, then pixels when it shows sixel images.
  std::vector<std::pair<CellMode, bool>> modes = {{CellMode::Ascii, false}};
  if (screen_.unicode() && screen_.colour()) modes.push_back({CellMode::HalfBlock, false});
  if (screen_.unicode()) modes.push_back({CellMode::Braille, false});
  if (screen_.sixel()) modes.push_back({mode_, true});
  size_t at = 0;
  for (size_t i = 0; i < modes.size(); ++i)
    if (modes[i].second == pixels_ && (pixels_ || modes[i].first == mode_)) at = i;
  auto next = modes[(at + 1) % modes.size()];
  if (!next.second) mode_ = next.first;
  pixels_ = next.second;
  sixelSent_ = false;
}

// ---- drawing

std::string TuiHost::stateText() const {
  if (past_ && pastShown_) return "back at " + stepName(pastShown_->step);
  if (ended_) return endState_;
  if (waitingFor_ && *waitingFor_) return waitingFor_;
  if (paused_) return "paused";
  return "running";
}

std::string TuiHost::titleState() const {
  if (past_ && pastShown_)
    return "back in time: " + stepName(pastShown_->step) + " of " +
           grouped(recording_.totalSteps());
  bool waiting = waitingFor_ && *waitingFor_;
  if (ended_ || !paused_ || !breakAt_.valid() || !(breakAt_ == loc_) || waiting) return stateText();
  // The title says why the run stopped; the status panel keeps the short state.
  std::string s = "paused at breakpoint, line " + std::to_string(loc_.line);
  if (loc_.file != 0 && sources_ && loc_.file < sources_->size()) {
    const std::string& name = sources_->file(loc_.file).name();
    s += " of " + name.substr(name.find_last_of('/') + 1);
  }
  return s;
}

ViewState TuiHost::viewState() const {
  if (loadFailed_) return ViewState::NotLoaded;
  if (past_) return ended_ ? ViewState::BackEnded : ViewState::BackPaused;
  if (ended_) return ViewState::Ended;
  return paused_ ? ViewState::Paused : ViewState::Running;
}

void TuiHost::draw() {
  lastFrame_ = Clock::now();
  // A real robot connected (or gone, rCommPort 0) changes the status panel's size.
  if (machine_ && (machine_->realRobot() != nullptr) != layoutReal_) needLayout_ = true;
  if (needLayout_) {
    bool real = machine_ && machine_->realRobot();
    layout_ = layoutTui(screen_.cols(), screen_.rows(), kStatusRows + (real ? kLinkRows : 0));
    layoutReal_ = real;
    needLayout_ = false;
    refreshVariables();
  }
  if (redraw_) {
    screen_.redrawAll();
    redraw_ = false;
    sixelSent_ = false;
  }
  screen_.beginFrame();
  if (layout_.tooSmall) {
    screen_.drawText(0, 0, "rb: the terminal is too small");
    screen_.drawText(
        0, 1, "(at least " + std::to_string(kMinCols) + " x " + std::to_string(kMinRows) + ")");
    screen_.drawText(0, 2, "F10 quits");
    screen_.present();
    return;
  }
  if (!paused_ && !ended_ && lastFrame_ - lastVariables_ >= kVariablesInterval) refreshVariables();
  TermStyle bar;
  bar.reverse = true;
  std::string title = " rb run " + settings_.fileName + "   " + titleState() + "   view " +
                      (pixels_ ? "pixels" : modeName(mode_));
  if (!pixelsNote_.empty()) title += "   " + pixelsNote_;
  // (After the end the run stays where it was: only the time shown bounds a notice then.)
  if (!notice_.empty() && ((!ended_ && loc_ == noticeLoc_) || lastFrame_ < noticeUntil_))
    title += "   " + notice_;
  title.resize(static_cast<size_t>(layout_.title.width), ' ');
  screen_.drawText(0, 0, title, bar);
  screen_.drawBox(layout_.arenaBox.col, layout_.arenaBox.row, layout_.arenaBox.width,
                  layout_.arenaBox.height, "arena 800x600");
  if (machine_) {
    drawArena();
    drawOverlays();
    drawStatus();
  }
  drawSource();
  drawVariables();
  drawOutput();
  TermStyle dim;
  dim.dim = true;
  if (prompting_) {
    // The line a watch is typed at takes the keys line's place.
    std::string line = "watch: " + promptText_ + "_";
    std::string help = "   Enter adds it (one watched already: removes it), Esc cancels";
    if (line.size() + help.size() <= static_cast<size_t>(layout_.keys.width)) line += help;
    if (line.size() > static_cast<size_t>(layout_.keys.width))
      line = line.substr(line.size() - static_cast<size_t>(layout_.keys.width));
    screen_.drawText(layout_.keys.col, layout_.keys.row, line);
  } else {
    screen_.drawText(layout_.keys.col, layout_.keys.row,
                     keysLine(layout_.keys.width, viewState(), programKeys_, settings_.watching),
                     dim);
  }
  screen_.present();
}

void TuiHost::drawArena() {
  Machine& m = *machine_;
  // An earlier step: its screen and pose from the recording. The text the program drew shows
  // as pixels there (the display list is the present's).
  bool past = past_ && pastShown_;
  render::RobotView robot = past ? pastShown_->robot : render::robotView(m);
  const Pixels& pixels = past ? pastShown_->screen : m.shownScreen();
  int64_t step = past ? static_cast<int64_t>(pastShownIndex_) : -1;
  const Rect& a = layout_.arena;
  const std::vector<DrawOp>& ops = m.canvas().displayList();
  bool stale = frame_.cols != a.width || frame_.rows != a.height || frameMode_ != mode_ ||
               frameStep_ != step || (!past && (frameCanvasVersion_ != m.canvas().version() ||
                                                m.showsFlip() || frameTextOps_ != ops.size())) ||
               !sameRobot(robot, frameRobot_);
  if (stale) {
    render::ArenaOptions options{a.width, a.height, mode_};
    if (!past) options.textOps = &ops;
    frame_ = render::renderArena(pixels, m.canvas().background(), robot, options);
    frameStep_ = step;
    frameCanvasVersion_ = m.canvas().version();
    frameRobot_ = robot;
    frameMode_ = mode_;
    frameTextOps_ = ops.size();
    sixelSent_ = false;
  }
  if (!pixels_) {
    screen_.drawArena(frame_, a.col, a.row);
    return;
  }
  // Pixels: the arena's cells stay blank (curses leaves them alone) and the image goes over them,
  // sent again only when the picture changed or the terminal was cleared.
  std::string blank(static_cast<size_t>(a.width), ' ');
  for (int r = 0; r < a.height; ++r) screen_.drawText(a.col, a.row + r, blank);
  if (sixelSent_) return;
  auto [cw, ch] = screen_.cellPixels();
  if (cw <= 0 || ch <= 0) {
    cw = 10;  // a terminal that does not tell its cell size: a common one
    ch = 20;
  }
  render::RgbImage image = render::composeImage(pixels, robot, 1);
  screen_.overlayAt(a.col, a.row, render::sixelImage(image, a.width * cw, a.height * ch));
  sixelSent_ = true;
}

void TuiHost::drawOverlays() {
  const Rect& a = layout_.arena;
  // Text inside the arena, cut at its edges.
  auto put = [&](int col, int row, std::string s, const TermStyle& style) {
    if (row < a.row || row >= a.row + a.height) return;
    if (col < a.col) {
      if (static_cast<int>(s.size()) <= a.col - col) return;
      s.erase(0, static_cast<size_t>(a.col - col));
      col = a.col;
    }
    int room = a.col + a.width - col;
    if (room <= 0) return;
    if (static_cast<int>(s.size()) > room) s.resize(static_cast<size_t>(room));
    screen_.drawText(col, row, s, style);
  };
  TermStyle banner;
  banner.reverse = true;
  banner.bold = true;
  if (past_ && pastShown_) {
    // The controls and dialogs are the present's: an earlier step shows the screen alone.
    if (!pixels_) put(a.col + 1, a.row, " BACK IN TIME  Left/Right step  Esc now ", banner);
    return;
  }
  // The program's controls, on the cells that show them (a click there hits them).
  const Controls& controls = machine_->controls;
  for (const Button& b : controls.buttons) {
    Rect cells = controlCells(b.x, b.y, b.width, b.height);
    if (cells.width <= 0) continue;
    TermStyle s;
    s.reverse = true;
    s.bold = b.name == controls.pressed;
    std::string label = b.name;
    if (static_cast<int>(label.size()) + 2 <= cells.width) label = "[" + label + "]";
    label.resize(static_cast<size_t>(cells.width), ' ');
    int labelRow = cells.row + cells.height / 2;
    for (int r = 0; r < cells.height; ++r)
      put(cells.col, cells.row + r,
          r + cells.row == labelRow ? label : std::string(static_cast<size_t>(cells.width), ' '), s);
  }
  for (const EditBox& e : controls.edits) {
    Rect cells = controlCells(e.x, e.y, e.width, e.height);
    if (cells.width <= 0) continue;
    int width = std::max(cells.width, 1);
    std::string field = e.text;
    if (static_cast<int>(field.size()) > width)
      field = field.substr(field.size() - static_cast<size_t>(width));
    field.resize(static_cast<size_t>(width), '_');
    TermStyle s;
    s.reverse = e.name == rules_.focusedEdit();
    s.underline = !s.reverse;
    put(cells.col, cells.row + cells.height / 2, field, s);
  }
  // (Over a sixel image the banner would be drawn over again: the title says paused.)
  if (paused_ && !ended_ && !pixels_)
    put(a.col + 1, a.row, " PAUSED  F2 run  F3 step  F7 over ", banner);
  if (box_) {
    int width = std::min(
        a.width - 2,
        std::max<int>(24, static_cast<int>(std::max(box_->text.size(), box_->title.size())) + 6));
    int inner = std::max(width - 4, 1);
    std::vector<std::string> lines;
    for (size_t i = 0; i < box_->text.size() || lines.empty(); i += static_cast<size_t>(inner))
      lines.push_back(box_->text.substr(i, static_cast<size_t>(inner)));
    if (static_cast<int>(lines.size()) > a.height - 6)
      lines.resize(static_cast<size_t>(std::max(1, a.height - 6)));
    int height = static_cast<int>(lines.size()) + 4;
    int col = a.col + (a.width - width) / 2, row = a.row + (a.height - height) / 2;
    TermStyle plain;
    for (int r = 0; r < height; ++r)
      put(col, row + r, std::string(static_cast<size_t>(width), ' '), plain);
    screen_.drawBox(col, row, width, height, box_->title);
    for (size_t i = 0; i < lines.size(); ++i)
      put(col + 2, row + 1 + static_cast<int>(i), lines[i], plain);
    put(col + (width - 6) / 2, row + height - 2, "[ OK ]", banner);
  }
}

void TuiHost::drawStatus() {
  Machine& m = *machine_;
  TuiStatus s;
  s.state = stateText();
  s.speedFactor = clock_.factor();
  s.rSpeed = m.robotSpeed;
  Robot& robot = m.robot();
  s.located = robot.located();
  const Pose& pose = robot.pose();
  s.x = pose.pos.x();
  s.y = pose.pos.y();
  s.heading = pose.heading;
  s.pen = robot.penDown();
  if (past_ && pastShown_) {
    // An earlier step: its pose; what the sensors read then is not kept.
    const RecordedStep& step = pastShown_->step;
    s.located = step.located;
    s.x = step.x;
    s.y = step.y;
    s.heading = step.heading;
    s.pen = step.pen;
    s.sensors = false;
  }
  // Read without a trace event, a random number or a robot command: the simulator's sensors
  // now, or what a real robot reported last.
  if (std::optional<QuietReadings> r = robot.quietReadings(); r && s.sensors) {
    s.bumper = r->bumper;
    s.feel = r->feel;
  }
  if (const RealRobot* real = m.realRobot()) {
    const RealRobot::LinkStats& link = real->linkStats();
    s.real = true;
    s.port = real->name();
    s.commands = link.commands;
    if (link.replies > 0) {
      // The sensor bytes as they came over the wire (bumper, feel, sense), then the result.
      const auto wire = protocol::encodeReply(link.last);
      s.lastReply = "cmd " + std::to_string(link.lastCode) + "," + std::to_string(link.lastParam) +
                    " -> " + protocol::hexBytes(wire.data(), 3) + " = " + std::to_string(link.last.result);
    }
    if (!link.fault.empty()) s.lastReply = link.fault;
  }
  s.range = past_ && pastShown_ ? pastShown_->range : lastRange_;
  const Rect& r = layout_.status;
  std::vector<std::string> lines = r.height >= static_cast<int>(statusLines(s, r.width).size())
                                       ? statusLines(s, r.width - 1)
                                       : compactStatusLines(s, r.width);
  for (int i = 0; i < r.height && i < static_cast<int>(lines.size()); ++i)
    screen_.drawText(r.col, r.row + i, lines[static_cast<size_t>(i)]);
}

void TuiHost::drawSource() {
  const Rect& box = layout_.sourceBox;
  if (box.height <= 0 || !sources_ || sources_->size() == 0) return;
  SourceLoc loc = shownLoc();
  uint32_t fileIndex = loc.valid() && loc.file < sources_->size() ? loc.file : 0;
  const SourceFile& file = sources_->file(fileIndex);
  std::string name = file.name();
  size_t slash = name.find_last_of('/');
  if (slash != std::string::npos) name = name.substr(slash + 1);
  // A box when there is room for one, else a header line.
  Rect inner = layout_.source;
  if (inner.height <= 0) {
    TermStyle dim;
    dim.dim = true;
    std::string header = "-- " + name + " ";
    header.resize(static_cast<size_t>(box.width), '-');
    screen_.drawText(box.col, box.row, header, dim);
    inner = {box.col, box.row + 1, box.width, box.height - 1};
  } else {
    screen_.drawBox(box.col, box.row, box.width, box.height, name);
  }
  auto marked = [&](uint32_t line) { return debugger_.hasBreakpoint(fileIndex, line); };
  // After the end nothing runs: no line is marked as the one about to (an earlier step's is).
  bool running = !ended_ || (past_ && loc.valid());
  // After the end, the error's line is marked ('!', in red) and the pane shows it.
  const bool showError = ended_ && !past_ && errorLoc_.valid() && errorLoc_.file == fileIndex;
  std::vector<PaneLine> lines = sourceLines(file, showError ? errorLoc_.line : loc.line, inner.height, inner.width,
                                            marked, running, showError ? errorLoc_.line : 0);
  for (size_t i = 0; i < lines.size(); ++i) {
    TermStyle s;
    std::string text = lines[i].text;
    if (lines[i].highlight) {
      s.reverse = true;
      s.bold = true;
      text.resize(static_cast<size_t>(inner.width), ' ');
    } else if (lines[i].error) {
      s.colour = screen_.colour();
      s.fg = 0xFFFFFF;
      s.bg = 0xAA0000;
      s.bold = true;
      s.reverse = !screen_.colour();
      text.resize(static_cast<size_t>(inner.width), ' ');
    } else if (lines[i].marked) {
      s.colour = screen_.colour();
      s.fg = 0xFF5555;
      s.bg = 0x000000;
      s.bold = !screen_.colour();
    }
    screen_.drawText(inner.col, inner.row + static_cast<int>(i), text, s);
  }
}

void TuiHost::drawVariables() {
  const Rect& box = layout_.varsBox;
  if (box.height <= 0 || layout_.vars.height <= 0) return;
  // Variables are not kept for earlier steps: the title says whose they are.
  std::string title = past_ && pastShown_
                          ? "variables now, not at " + stepName(pastShown_->step)
                          : std::string("variables");
  int shown = layout_.vars.height;
  int total = static_cast<int>(varLines_.size());
  varScroll_ = std::clamp(varScroll_, 0, std::max(total - shown, 0));
  if (total > shown)
    title += " " + std::to_string(varScroll_ + 1) + "-" +
             std::to_string(std::min(varScroll_ + shown, total)) + " of " + std::to_string(total);
  screen_.drawBox(box.col, box.row, box.width, box.height, title);
  for (int i = 0; i < shown && varScroll_ + i < total; ++i)
    screen_.drawText(layout_.vars.col, layout_.vars.row + i,
                     varLines_[static_cast<size_t>(varScroll_ + i)]);
}

void TuiHost::drawOutput() {
  const Rect& r = layout_.output;
  if (r.height < 1) return;
  bool past = past_ && pastShown_;
  TermStyle dim;
  dim.dim = true;
  barWidth_ = 0;
  if (timelineShown() && recording_.totalSteps() > 0) {
    // Paused or at the end, the header is the timeline: where the step shown is in the run.
    size_t present = stepsBeforePresent();
    std::string label =
        past ? "output at " + stepName(pastShown_->step) + " of " +
                   grouped(recording_.totalSteps())
        : ended_ ? "output at the end (" + grouped(recording_.totalSteps()) + " steps)"
                 : "output at step " + grouped(recording_.totalSteps()) + " (now)";
    int col = 0;
    std::string rule = timelineRule(r.width, label, past ? *past_ : present, present + 1, col,
                                    barWidth_);
    barCol_ = r.col + col;
    screen_.drawText(r.col, r.row, rule, dim);
  } else {
    std::string header = "-- output ";
    header.resize(static_cast<size_t>(r.width), '-');
    screen_.drawText(r.col, r.row, header, dim);
  }
  int room = r.height - 1;
  std::vector<std::string> rows;
  if (past) {
    // What had been printed when that step began: the transcript up to its count of bytes.
    uint64_t upTo = pastShown_->step.output;
    std::string_view text(transcript_);
    text = text.substr(0, std::min<uint64_t>(upTo, text.size()));
    if (upTo > transcript_.size() && room > 0) {
      screen_.drawText(r.col, r.row + r.height - 1, "(output past the view's 64 MiB is not kept)",
                       dim);
      --room;
    }
    rows = lastRows(lastLines(text, static_cast<size_t>(std::max(room, 0))), r.width, room);
    for (size_t i = 0; i < rows.size(); ++i)
      screen_.drawText(r.col, r.row + 1 + static_cast<int>(i), rows[i]);
    return;
  }
  std::vector<std::string_view> shown(lines_.begin(), lines_.end());
  std::string last;
  if (inputActive_) last = partial_ + inputPrompt_ + inputText_ + "_";
  else last = partial_;
  if (!last.empty()) shown.push_back(last);
  if (!error_.empty()) {
    // The error wraps at its words, so that its hint ("did you mean ...") is never cut off; it
    // keeps its rows at the bottom and the output above gets what is left.
    std::vector<std::string> errorRows;
    for (size_t at = 0; at <= error_.size();) {
      size_t end = std::min(error_.find('\n', at), error_.size());
      for (std::string& row : wordRows(std::string_view(error_).substr(at, end - at), r.width))
        errorRows.push_back(std::move(row));
      at = end + 1;
    }
    if (static_cast<int>(errorRows.size()) > room)
      errorRows.resize(static_cast<size_t>(std::max(room, 0)));
    room -= static_cast<int>(errorRows.size());
    TermStyle errorStyle;
    errorStyle.bold = true;
    errorStyle.colour = screen_.colour();
    errorStyle.fg = 0xFF5555;
    errorStyle.bg = 0x000000;
    errorStyle.reverse = !screen_.colour();
    for (size_t i = 0; i < errorRows.size(); ++i)
      screen_.drawText(r.col, r.row + 1 + room + static_cast<int>(i), errorRows[i], errorStyle);
  }
  rows = lastRows(shown, r.width, room);
  for (size_t i = 0; i < rows.size(); ++i)
    screen_.drawText(r.col, r.row + 1 + static_cast<int>(i), rows[i]);
}

}  // namespace rb::tui
