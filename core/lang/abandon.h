#pragma once
// The front end's one way out of a statement it cannot read or compile.

namespace rb {

/// Thrown by the parser and the compiler right after they put an error in the DiagnosticList,
/// to abandon the statement at hand; caught where the next statement begins (the next line,
/// for the parser). It never leaves loadProgram or compileProgram: their callers see
/// diagnostics only.
struct StatementAbandoned {};

}  // namespace rb
