// rb: a RobotBASIC toolchain. This file only wires the subcommands together and maps outcomes
// to exit codes; each subcommand lives in its own *_command.cpp.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <string>

#include "check_command.h"
#include "cli_errors.h"
#include "exit_codes.h"
#include "ports_command.h"
#include "lsp_command.h"
#include "render_command.h"
#include "robot_command.h"
#include "run_command.h"
#include "test_command.h"
#include "test_job.h"
#include "trace_command.h"

int main(int argc, char** argv) {
  CLI::App app{"rb: run, check, trace, render and test RobotBASIC programs", "rb"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rb " RB_VERSION);
  int exitCode = rb::exitcode::kOk;
  rb::cli::addRunCommand(app, exitCode);
  rb::cli::addCheckCommand(app, exitCode);
  rb::cli::addTraceCommand(app, exitCode);
  rb::cli::addRenderCommand(app, exitCode);
  rb::cli::addRobotCommand(app, exitCode);
  rb::cli::addPortsCommand(app, exitCode);
  rb::cli::addTestCommand(app, exitCode);
  rb::cli::addTestJobCommand(app, exitCode);
  rb::cli::addLspCommand(app, exitCode);
  app.footer("Run 'rb COMMAND --help' (or 'rb help COMMAND') for the options of a command. "
             "Manual: man rb.");
  rb::cli::useRbFailureMessages(app);
  if (std::optional<int> code = rb::cli::precheckCommandLine(app, argc, argv)) return *code;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return rb::exitcode::kUsage;
  }
  // Whatever a command printed must have reached its reader: a full disk or a closed pipe is
  // a failure (exit 74), never a silent success. Commands that write a lot check as they go.
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    if (exitCode == rb::exitcode::kOk || exitCode == rb::exitcode::kRejected) {
      std::string name = app.get_subcommands().empty() ? "rb" : "rb " + app.get_subcommands().front()->get_name();
      std::fprintf(stderr, "%s: error: cannot write to standard output\n", name.c_str());
      exitCode = rb::exitcode::kIoError;
    }
  }
  return exitCode;
}
