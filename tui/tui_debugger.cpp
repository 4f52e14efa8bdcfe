#include "tui_debugger.h"

#include <algorithm>

namespace rb::tui {

StatementLines::StatementLines(const Program& program) {
  for (size_t pc = 0; pc < program.code.size() && pc < program.locs.size(); ++pc) {
    if (program.code[pc].op != Op::Line) continue;
    const SourceLoc& loc = program.locs[pc];
    if (!loc.valid()) continue;
    if (loc.file >= lines_.size()) lines_.resize(loc.file + 1);
    lines_[loc.file].push_back(loc.line);
  }
  for (std::vector<uint32_t>& l : lines_) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  }
}

bool StatementLines::has(uint32_t file, uint32_t line) const {
  return file < lines_.size() && std::binary_search(lines_[file].begin(), lines_[file].end(), line);
}

uint32_t StatementLines::atOrAfter(uint32_t file, uint32_t line) const {
  if (file >= lines_.size()) return 0;
  auto it = std::lower_bound(lines_[file].begin(), lines_[file].end(), line);
  return it == lines_[file].end() ? 0 : *it;
}

BreakpointPlace placeBreakpoint(const StatementLines& lines, uint32_t file, uint32_t line) {
  BreakpointPlace p;
  p.line = lines.atOrAfter(file, line);
  if (p.line == line) return p;
  if (p.line == 0) {
    p.note = "no statement on or after line " + std::to_string(line) +
             ": nothing there can stop the run";
    return p;
  }
  p.moved = true;
  p.note = "line " + std::to_string(line) + " holds no statement: the breakpoint is on line " +
           std::to_string(p.line) + ", the next that does";
  return p;
}

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

}  // namespace rb::tui
