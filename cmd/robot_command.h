#pragma once
// `rb robot --pty`: a robot emulator on a pseudo-terminal, for tests and for users without a
// robot. The emulation itself lives in drivers/.

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addRobotCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
