#pragma once
// rb's command-line mistakes in one voice, as git and cargo word them: every message starts
// "rb <command>: error:", names the word at fault, suggests the nearest command or option, and
// rb exits 64. CLI11 parses; this file looks at the command line first for what CLI11 words
// poorly, and replaces CLI11's failure message.

#include "cli_app.h"
#include <optional>

namespace rb::cli {

/// Before CLI11 parses: no command at all (prints the usage), `rb help [COMMAND]`, an unknown
/// command (a program where the command belongs, `rb square.bas`, suggests `rb run`), an
/// unknown option of a known command. Returns the exit code when rb should stop here (the
/// message printed), nullopt to go on parsing.
std::optional<int> precheckCommandLine(CLI::App& app, int argc, char** argv);

/// Makes CLI11's own failures (a missing file, a bad value) print in rb's form.
void useRbFailureMessages(CLI::App& app);

}  // namespace rb::cli
