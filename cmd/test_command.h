#pragma once
// `rb test [PATH...]`: grades programs against the expectations in their comments or an
// assignment file, several at a time, each in a child process (grade/).

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addTestCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
