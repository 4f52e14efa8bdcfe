#pragma once
// `rb trace FILE`: runs a program headless and prints what the robot did, one line per event.

#include <CLI/CLI.hpp>

namespace rb::cli {

void addTraceCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
