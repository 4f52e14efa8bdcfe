#pragma once
// `rb run --tui`: the program runs live in an ncurses view of the arena.

#include "run_options.h"

namespace rb::tui {

/// Runs opts.file in the terminal view; returns rb's exit code.
int runTui(const run::RunOptions& opts);

}  // namespace rb::tui
