#pragma once
// When the live view pauses a running program: single steps (one statement, stepping into a
// gosub or sub call; one statement, stepping over them; one pixel or degree of robot motion)
// and breakpoints on lines. The view asks before each statement and after each robot step.

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/source.h"
#include "lang/bytecode.h"

namespace rb::tui {

/// The lines of each file of a program where a run can stop: those that hold a statement, as
/// the compiler marks them for line tracing (the host's onLine is called only there). Comments,
/// blank lines, labels, `sub` and `endsub` lines hold none; `else`, `next`, `wend` and `until`
/// lines do (their statement runs when the run comes to them).
class StatementLines {
 public:
  /// From `program`, compiled with CompileOptions::lineTracing.
  explicit StatementLines(const Program& program);
  bool has(uint32_t file, uint32_t line) const;
  /// The first line at or after `line` of `file` that holds a statement; 0 when none does.
  uint32_t atOrAfter(uint32_t file, uint32_t line) const;

 private:
  std::vector<std::vector<uint32_t>> lines_;  ///< by file: sorted, each once
};

/// Where a breakpoint asked for on a line goes (a breakpoint must be on a statement to stop).
struct BreakpointPlace {
  uint32_t line = 0;  ///< the line it goes on; 0: refused (no statement on or after the line)
  bool moved = false;  ///< the line asked for holds no statement: the next one that does
  /// What happened, for the title and standard error ("" when the line was taken as asked):
  /// "line 3 holds no statement: the breakpoint is on line 5, the next that does" or
  /// "no statement on or after line 40: nothing there can stop the run".
  std::string note;
};
/// Places a breakpoint asked for on `line` of `file`.
BreakpointPlace placeBreakpoint(const StatementLines& lines, uint32_t file, uint32_t line);

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
  /// Every breakpoint: (file, line), in order.
  const std::set<std::pair<uint32_t, uint32_t>>& breakpoints() const { return breaks_; }

 private:
  Step step_ = Step::None;
  size_t depth_ = 0;
  SourceLoc last_;  ///< the previous statement
  bool atBreakpoint_ = false;
  std::set<std::pair<uint32_t, uint32_t>> breaks_;
};

}  // namespace rb::tui
