#include "tui_debugger.h"

namespace rb::cli {

void Debugger::step(Step kind, size_t depth) {
  step_ = kind;
  depth_ = depth;
}

bool Debugger::pauseAtStatement(SourceLoc loc, size_t depth) {
  // A breakpoint stops the run when it comes to the line: from another line, or back to the
  // line's start (a loop on one line); not at each further statement of a line it is on.
  bool arrived = loc.file != last_.file || loc.line != last_.line || loc.col <= last_.col;
  last_ = loc;
  bool pause = arrived && hasBreakpoint(loc.file, loc.line);
  atBreakpoint_ = pause;
  switch (step_) {
    case Step::None: break;
    case Step::Into:
    case Step::Robot: pause = true; break;
    case Step::Over: pause = pause || depth <= depth_; break;
  }
  if (pause) step_ = Step::None;
  return pause;
}

bool Debugger::pauseAtRobotStep() {
  if (step_ != Step::Robot) return false;
  step_ = Step::None;
  return true;
}

bool Debugger::toggleBreakpoint(uint32_t file, uint32_t line) {
  auto key = std::make_pair(file, line);
  if (breaks_.erase(key)) return false;
  breaks_.insert(key);
  return true;
}

}  // namespace rb::cli
