#pragma once
// The standard built-in table: every RobotBASIC command, function and constant rb knows, with
// the handlers that run them on a Machine. Its rows are in builtins.cpp and in the
// builtins_*.cpp of each family; lang/builtins.h is the mechanism they are written in.

#include "lang/builtins.h"

namespace rb {

/// The standard table, built on first use and never changed afterwards. Programs are loaded and
/// compiled against it (loadProgram) and dispatch through it when they run.
const BuiltinTable& standardBuiltins();

}  // namespace rb
