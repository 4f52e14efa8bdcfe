#pragma once
// `rb render FILE -o OUT`: runs a program headless and writes its final screen as PNG, SVG or
// text.

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addRenderCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
