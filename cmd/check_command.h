#pragma once
// `rb check FILE...`: finds errors without running anything, in compiler format.

#include <CLI/CLI.hpp>

namespace rb::cli {

void addCheckCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
