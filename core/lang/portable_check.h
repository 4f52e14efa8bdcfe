#pragma once
// `rb check --portable` (and the language server's `rb.portable` setting): warnings, rule
// rb-not-portable, wherever a program uses what no public RobotBASIC source shows: a built-in
// whose evidence (Builtin::evidence, machine/builtins_evidence.cpp) says it is rb's own, or a
// statement form rb accepts beyond RobotBASIC's sources (`else if`, `end if`, `endsub`, `step`,
// `continue`, `mod`, `'` comments, ...; the list is docs/compatibility.md's "Statement forms").
// Each warning is followed by a note saying what RobotBASIC is known to have instead, where
// there is such a thing.

#include "base/diagnostic.h"
#include "lang/loader.h"

namespace rb {

/// Adds the portability warnings of `program` (every file of it: the main file and its
/// includes) to `diags`, each with its note, in program order; the caller sorts.
void checkPortable(const LoadedProgram& program, DiagnosticList& diags);

}  // namespace rb
