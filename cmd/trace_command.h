#pragma once
// `rb trace FILE`: runs a program headless and prints what the robot did, one line per event.

#include "cli_app.h"

namespace rb::cli {

void addTraceCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
