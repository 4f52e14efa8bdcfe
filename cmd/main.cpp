// rb: a RobotBASIC toolchain. This file only wires the subcommands together and maps outcomes
// to exit codes; each subcommand lives in its own *_command.cpp.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iterator>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

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
  int exitCode = rb::run::exitcode::kOk;
  // The command that runs gets its options; the others only their names and descriptions,
  // which is all that rb --help and an unknown command's message show (building every
  // command's options was a fifth of the start-up of an empty program). When the first word
  // is no command (help, --help, a mistake), every command gets its options.
  struct Command {
    const char* name;
    void (*add)(CLI::App&, int&, bool);
  };
  static constexpr Command kCommands[] = {
      {"run", rb::cli::addRunCommand},       {"check", rb::cli::addCheckCommand},
      {"trace", rb::cli::addTraceCommand},   {"render", rb::cli::addRenderCommand},
      {"robot", rb::cli::addRobotCommand},   {"ports", rb::cli::addPortsCommand},
      {"test", rb::cli::addTestCommand},     {rb::cli::kTestJobCommand, rb::cli::addTestJobCommand},
      {"lsp", rb::cli::addLspCommand},       {rb::cli::kTestSimilarityCommand, rb::cli::addTestSimilarityCommand},
  };
  std::string_view wanted = argc > 1 ? argv[1] : "";
  if (wanted == "help" && argc > 2) wanted = argv[2];
  const bool known = std::any_of(std::begin(kCommands), std::end(kCommands),
                                 [&](const Command& c) { return wanted == c.name; });
  for (const Command& c : kCommands) {
    c.add(app, exitCode, !known || wanted == c.name);
    auto added = app.get_subcommands([](const CLI::App*) { return true; });
    if (added.empty() || added.back()->get_name() != c.name) {  // the table names each command
      std::fprintf(stderr, "rb: internal error: command '%s' is misnamed\n", c.name);
      return rb::run::exitcode::kRuntime;
    }
  }
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
    return rb::run::exitcode::kUsage;
  }
  // Whatever a command printed must have reached its reader: a full disk or a closed pipe is
  // a failure (exit 74), never a silent success. Commands that write a lot check as they go.
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    if (exitCode == rb::run::exitcode::kOk || exitCode == rb::run::exitcode::kRejected) {
      std::string name = app.get_subcommands().empty() ? "rb" : "rb " + app.get_subcommands().front()->get_name();
      std::fprintf(stderr, "%s: error: cannot write to standard output\n", name.c_str());
      exitCode = rb::run::exitcode::kIoError;
    }
  }
  return exitCode;
}
