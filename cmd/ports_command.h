#pragma once
// `rb ports`: the serial ports a real robot may be on, and the --port number of each.

#include "cli_app.h"

namespace rb::cli {

void addPortsCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
