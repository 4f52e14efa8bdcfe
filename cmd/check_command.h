#pragma once
// `rb check FILE...`: finds errors without running anything, in compiler format.

#include "cli_app.h"

namespace rb::cli {

void addCheckCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
