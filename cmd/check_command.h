#pragma once
// `rb check FILE...`: finds errors without running anything, in compiler format.

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addCheckCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
