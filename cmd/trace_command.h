#pragma once
// `rb trace FILE`: runs a program headless and prints what the robot did, one line per event.

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addTraceCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
