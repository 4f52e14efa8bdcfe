#pragma once
// `rb lsp`: the language server (lsp/) on standard input and output, for editors.

#include "cli_app.h"

namespace rb::cli {

/// Without options: only the command's name and description (see main.cpp).
void addLspCommand(CLI::App& app, int& exitCode, bool withOptions = true);

}  // namespace rb::cli
