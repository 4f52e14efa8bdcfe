#pragma once
// `rb run FILE`: runs a program headless on the simulator (output on stdout, diagnostics on
// stderr).

#include "cli_app.h"
#include "run_options.h"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rb::cli {


}  // namespace rb::cli

namespace CLI {
class Validator;
}

namespace rb::cli {

/// How every command checks its numbers (run_command.cpp): seconds of a limit, of a robot's answer,
/// statements, MiB, baud, programs at once; each with its range in the message.
extern const CLI::Validator kSeconds, kLimitSeconds, kPositiveSeconds, kStepCount, kMebibytes, kBaud, kJobs;

/// Adds the options shared by run, trace and render: limits, seed, real robot, scripted input.
void addRunLimitOptions(CLI::App& app, run::RunOptions& opts);

/// Without options: only the command's name and description (see main.cpp).
void addRunCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
