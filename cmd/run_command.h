#pragma once
// `rb run FILE`: runs a program headless on the simulator (output on stdout, diagnostics on
// stderr).

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

namespace rb::cli {

/// Options every subcommand that runs a program shares (run, trace, render).
struct RunOptions {
  std::string file;
  std::optional<uint64_t> seed;
  uint64_t maxSteps = 0;
  double timeoutSeconds = 0;
};

/// Adds --seed, --max-steps and --timeout to a subcommand.
void addRunLimitOptions(CLI::App& app, RunOptions& opts);

void addRunCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
