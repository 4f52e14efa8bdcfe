#pragma once
// Checks `rb check` adds to what the compiler finds: warnings about likely mistakes that do not
// stop a program from loading.

#include "diagnostic.h"
#include "loader.h"

namespace rb {

/// Warns about every variable that is read somewhere but assigned nowhere in its scope (the main
/// program or a sub). Such a read is a runtime error, and usually a case slip: `real` vs `Real`.
void lintProgram(const LoadedProgram& program, DiagnosticList& diags);

}  // namespace rb
