#pragma once
// Checks `rb check` adds to what the compiler finds: warnings about likely mistakes that do not
// stop a program from loading.

#include <memory>

#include "base/diagnostic.h"
#include "lang/compiler.h"
#include "lang/loader.h"

namespace rb {

struct LintOptions {
  /// The program is meant for a real robot (`rb check --target rb9`), which needs no rLocate.
  bool realRobot = false;
  /// The robot is placed before the program starts (rb test's world program placed it), so a
  /// robot statement before the program's own rLocate is no mistake.
  bool robotPlaced = false;
};

/// Warns about every variable that is read somewhere but assigned nowhere in its scope (the main
/// program or a sub). Such a read is a runtime error, and usually a case slip: `real` vs `Real`.
/// And, in a program without errors, about what its flow shows (flow_check.h): a loop whose
/// condition nothing in it changes, a robot statement before rLocate, a goto or gosub into a
/// sub, a sub never called and a label never used.
void lintProgram(const LoadedProgram& program, DiagnosticList& diags, const LintOptions& options = {});

/// lintProgram() fed one statement at a time, for walking the program once with the compiler
/// (CompileOptions::onStatement): statement() for every statement in order, then finish() once
/// the compiler's diagnostics are in.
class Linter {
 public:
  explicit Linter(const LoadedProgram& program, const LintOptions& options = {});
  ~Linter();
  Linter(const Linter&) = delete;
  Linter& operator=(const Linter&) = delete;
  void statement(const ast::Stmt& s, size_t index);
  void finish(DiagnosticList& diags);

 private:
  struct State;
  std::unique_ptr<State> st_;
};

/// The compile step every front end shares after loading (the command line's runs and checks,
/// the language server, the browser): the compiler, and with `lint` rb check's warnings from
/// the same walk over the statements; the diagnostics sorted by place.
std::unique_ptr<Program> compileChecked(const LoadedProgram& program, const CompileOptions& options, bool lint,
                                        DiagnosticList& diags, const LintOptions& lintOptions = {});

/// `rb check --target rb9`: warns where a program asks the RB-9 robot for what it cannot do:
/// a single rForward with a constant distance above 250 (the seed document's limit), and the
/// functions with no RB-9 hardware behind them (rLook: no camera; rGPSX/rGPSY: no GPS;
/// rChargeLevel: no battery command in the protocol). docs/real-robot.md lists the choices.
void checkRb9Target(const LoadedProgram& program, DiagnosticList& diags);

}  // namespace rb
