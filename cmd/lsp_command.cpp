#include "lsp_command.h"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "files.h"
#include "lsp/server.h"
#include "machine/builtins.h"

namespace rb::cli {

void addLspCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto stdio = std::make_shared<bool>(false);
  CLI::App* lsp = app.add_subcommand(
      "lsp", "Language server for editors: diagnostics, hover, completion, go to definition "
             "(Language Server Protocol on standard input and output)");
  if (!withOptions) return;
  // Editors' LSP clients (VS Code's among them) add --stdio when they talk over pipes, which is
  // the only transport rb has.
  lsp->add_flag("--stdio", *stdio, "Talk over standard input and output (the default and only transport)");
  lsp->footer(
      "Started by an editor, not by hand: it reads LSP messages on standard input and answers on "
      "standard output until the editor sends exit. Diagnostics come from the same checks as rb "
      "check. Setup for VS Code, Neovim, Helix and others: docs/editors.md. Exit status: 0 after "
      "shutdown and exit, 1 when the input ends without them.");
  // The callback holds the flag's storage, so it lives as long as the App that parses into it.
  lsp->callback([&exitCode, stdio] {
    (void)stdio;
    std::ios::sync_with_stdio(false);
    std::cin.tie(nullptr);
    run::FileSourceReader reader;
    lsp::ServerOptions options;
    options.load.libraryDirs = run::libraryDirs();
    options.version = RB_VERSION;
    lsp::Server server(std::cout, reader, standardBuiltins(), options);
    exitCode = server.run(std::cin);
  });
}

}  // namespace rb::cli
