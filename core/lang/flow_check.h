#pragma once
// The warnings of `rb check` that follow the program's flow: a loop whose condition nothing in
// the loop changes, a robot statement before the robot is placed, a goto or gosub into a sub,
// a sub never called and a label never used.
//
// The Linter (checker.h) hands over the statements one at a time, as the compiler reads them;
// each becomes a few events in one list of 32-bit words (a block's opener and closer, a jump, a
// call, a variable assigned, a robot statement), and finish() decides over that list once the
// whole program is known. Whatever the checks cannot follow (a goto out of a loop, an array
// element, a sensor in a condition) makes them stay quiet: a warning here is meant to be true.

#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>

#include "base/diagnostic.h"
#include "lang/ast.h"
#include "lang/loader.h"

namespace rb {

class FlowChecks {
 public:
  /// `realRobot`: the program is meant for a real robot (`rb check --target rb9`), which is never
  /// placed, so robot statements before rLocate are no news.
  FlowChecks(const LoadedProgram& program, bool realRobot);
  ~FlowChecks();
  FlowChecks(const FlowChecks&) = delete;
  FlowChecks& operator=(const FlowChecks&) = delete;

  /// The number of a variable as a statement's scope sees it (the main program's `x` and a sub's
  /// `_x` are one variable; a sub's own `x` another): given by the Linter, which knows the scopes.
  using Resolve = std::function<uint32_t(std::string_view name)>;

  /// A new variable number, whether it is a global variable (as opposed to a sub's own), and its
  /// name (a global's without its leading '_').
  void declareVariable(uint32_t var, bool global, std::string_view name);
  /// The statements of sub number `span` (an index into LoadedProgram::subSpans) begin.
  void enterSub(size_t span);
  /// The sub's statements end (before the statement that follows them).
  void leaveSub();
  /// One statement, in program order (the sub statement itself after enterSub()).
  void statement(const ast::Stmt& s, const Resolve& resolve);
  /// The statement just given assigns (or may assign: an output or by-reference argument) `var`.
  void write(uint32_t var);
  /// Decides and adds the warnings. Nothing when `diags` holds an error: a program that does not
  /// compile has no flow to follow (and no cascade of warnings from one mistake).
  void finish(DiagnosticList& diags);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rb
