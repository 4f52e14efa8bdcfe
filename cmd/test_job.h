#pragma once
// `rb test-job` (hidden): runs one program exactly as `rb run` would (same options, same
// output, same exit status) and also writes what `rb test` grades: a JSON record of rb check's
// diagnostics and of the run (record/record.h), and the final screen when asked. `rb test`
// starts one of these per program run, so each runs in a process of its own.

#include "cli_app.h"

namespace rb::cli {

/// The name of the hidden subcommand.
constexpr const char* kTestJobCommand = "test-job";

/// Without options: only the command's name and description (see main.cpp).
void addTestJobCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
