#pragma once
// Checks `rb check` adds to what the compiler finds: warnings about likely mistakes that do not
// stop a program from loading.

#include "base/diagnostic.h"
#include "lang/loader.h"

namespace rb {

/// Warns about every variable that is read somewhere but assigned nowhere in its scope (the main
/// program or a sub). Such a read is a runtime error, and usually a case slip: `real` vs `Real`.
void lintProgram(const LoadedProgram& program, DiagnosticList& diags);

/// `rb check --target rb9`: warns where a program asks the RB-9 robot for what it cannot do:
/// a single rForward with a constant distance above 250 (the seed document's limit), and the
/// functions with no RB-9 hardware behind them (rLook: no camera; rGPSX/rGPSY: no GPS;
/// rChargeLevel: no battery command in the protocol). docs/real-robot.md lists the choices.
void checkRb9Target(const LoadedProgram& program, DiagnosticList& diags);

}  // namespace rb
