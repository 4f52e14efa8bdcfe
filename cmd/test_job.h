#pragma once
// `rb test-job` (hidden): runs one program exactly as `rb run` would (same options, same
// output, same exit status) and also writes what `rb test` grades: a JSON record of rb check's
// diagnostics and of the run (record/record.h), and the final screen when asked. `rb test`
// starts one of these per program run, so each runs in a process of its own.

#include "cli_app.h"
#include "pool.h"

namespace rb::cli {

/// The name of the hidden subcommand.
constexpr const char* kTestJobCommand = "test-job";

/// Without options: only the command's name and description (see main.cpp).
void addTestJobCommand(CLI::App& app, int& exitCode, bool withOptions = true);

/// Runs one of rb test's jobs in this process rather than in a child: its standard input, output
/// and error and its working folder are the job's for its time, its options parsed as `rb
/// test-job` parses them; rb's own rules confine the program (run/sandbox.h), not the kernel's.
/// rb test --in-process grades with it (GradeOptions::runJob): the browser's way of grading.
grade::JobOutcome runJobInProcess(const grade::Job& job);

}  // namespace rb::cli
