#pragma once
// `rb render FILE -o OUT`: runs a program headless and writes its final screen as PNG, SVG or
// text.

#include "cli_app.h"

namespace rb::cli {

void addRenderCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
