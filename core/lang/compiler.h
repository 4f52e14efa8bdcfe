#pragma once
// Compiles a loaded program to the flat instruction list of bytecode.h: pairs block statements,
// resolves labels to addresses and variables to slots, checks calls against the built-in table
// and the program's subs. Everything `rb run` rejects before running is found here, so `rb
// check` and `rb run` agree by construction.

#include <functional>
#include <memory>

#include "lang/bytecode.h"
#include "base/diagnostic.h"
#include "lang/loader.h"

namespace rb {

struct CompileOptions {
  /// Emit a Line instruction at every statement (for `rb trace --lines` and single-stepping).
  bool lineTracing = false;
  /// Keep the instructions. Off for `rb check` without --dump-code: every instruction is still
  /// generated (so every error is found) but none is stored, and the program returned (when
  /// there are no errors) has subs, labels and names but no code.
  bool keepCode = true;
  /// Finish kept code (compiler_finish.cpp: by-reference outputs are not copied in, jumps to a
  /// return become the return). Off only in tests that compare the finished code with the plain.
  bool finish = true;
  /// Finish line-traced code too. A stepper that shows no variables (the web page's Step) may:
  /// the run is about twice as fast. Off for the live view and rb trace, which show every
  /// variable as the program wrote it (an output parameter's copy-in among them).
  bool finishTraced = false;
  /// Called with every statement of the program, in order, as the compiler reads it (with its
  /// index), so that other checks can walk the program in the same pass (see Linter).
  std::function<void(const ast::Stmt&, size_t)> onStatement;
};

/// Compiles `program`. Errors and warnings go to `diags`; the result is null when `diags` holds
/// any error (including those found while loading).
std::unique_ptr<Program> compileProgram(const LoadedProgram& program, const CompileOptions& options,
                                        DiagnosticList& diags);

}  // namespace rb
