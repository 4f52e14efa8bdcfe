#pragma once
// `rb lsp`: the language server (lsp/) on standard input and output, for editors.

#include "cli_app.h"

namespace rb::cli {

void addLspCommand(CLI::App& app, int& exitCode);

}  // namespace rb::cli
