#pragma once
// When the live view pauses a running program: single steps (one statement, stepping into a
// gosub or sub call; one statement, stepping over them; one pixel or degree of robot motion)
// and breakpoints on lines. The view asks before each statement and after each robot step.

#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>

#include "base/source.h"

namespace rb::cli {

class Debugger {
 public:
  enum class Step : uint8_t {
    None,
    Into,   ///< pause at the next statement, wherever it is
    Over,   ///< pause at the next statement not inside a gosub or sub called meanwhile
    Robot,  ///< pause after the next pixel or degree of robot motion (or the next statement)
  };

  /// Arms a step from the statement that is about to run, `depth` gosub/call frames deep.
  void step(Step kind, size_t depth);
  /// Forgets an armed step (the user resumed).
  void cancelStep() { step_ = Step::None; }
  Step armed() const { return step_; }

  /// Before a statement at `loc`, `depth` frames deep: true when the run pauses here (an armed
  /// step ends here, or the line has a breakpoint and the run just came to it).
  bool pauseAtStatement(SourceLoc loc, size_t depth);
  /// After pauseAtStatement returned true: whether a breakpoint stopped the run there (also
  /// when a step ended on the same statement).
  bool stoppedAtBreakpoint() const { return atBreakpoint_; }
  /// After a pixel or degree of robot motion: true when a robot step ends here.
  bool pauseAtRobotStep();

  /// Breakpoints by file (index in the program's SourceSet) and 1-based line.
  void addBreakpoint(uint32_t file, uint32_t line) { breaks_.insert({file, line}); }
  /// Sets or clears one; returns true when the line has a breakpoint now.
  bool toggleBreakpoint(uint32_t file, uint32_t line);
  bool hasBreakpoint(uint32_t file, uint32_t line) const {
    return !breaks_.empty() && breaks_.count({file, line}) != 0;
  }

 private:
  Step step_ = Step::None;
  size_t depth_ = 0;
  SourceLoc last_;  ///< the previous statement
  bool atBreakpoint_ = false;
  std::set<std::pair<uint32_t, uint32_t>> breaks_;
};

}  // namespace rb::cli
