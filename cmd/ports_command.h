#pragma once
// `rb ports`: the serial ports a real robot may be on, and the --port number of each.

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addPortsCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
