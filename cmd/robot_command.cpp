#include "robot_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "emulator_server.h"
#include "exit_codes.h"
#include "pty.h"
#include "robot_emulator.h"
#include "base/runtime_error.h"

namespace rb::cli {

namespace {

struct RobotOptions {
  bool pty = false;
  std::string link;
  int latencyMs = 0;
  bool verbose = false;
  drivers::EmulatorOptions emulator;
};

int executeRobot(const RobotOptions& opts) {
  if (!opts.pty) {
    std::fprintf(stderr, "rb robot: give --pty (the emulator serves a pseudo-terminal)\n");
    return run::exitcode::kUsage;
  }
  // Before the pty exists, so that a kill at any later moment still removes the link.
  drivers::StopSignals signals;
  try {
    drivers::Pty pty;
    std::optional<drivers::SymlinkGuard> link;
    if (!opts.link.empty()) link.emplace(opts.link, pty.slavePath());
    // The first line of stdout is the device to open; scripts wait for it.
    std::printf("%s\n", pty.slavePath().c_str());
    std::fflush(stdout);
    if (link) std::fprintf(stderr, "rb robot: %s -> %s\n", link->path().c_str(), pty.slavePath().c_str());
    drivers::RobotEmulator emulator(opts.emulator);
    drivers::ServeOptions serve;
    serve.latencyMs = opts.latencyMs;
    serve.log = opts.verbose ? stderr : nullptr;
    drivers::ServeEnd end = drivers::serveRobot(pty, emulator, serve, [&signals] { return signals.requested(); });
    if (end == drivers::ServeEnd::Died)
      std::fprintf(stderr, "rb robot: closed the port after %llu commands (--die-after)\n",
                   static_cast<unsigned long long>(emulator.commands()));
  } catch (const RuntimeError& e) {
    std::fprintf(stderr, "rb robot: %s\n", e.what());
    return run::exitcode::kIoError;
  }
  return run::exitcode::kOk;
}

}  // namespace

void addRobotCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<RobotOptions>();
  CLI::App* robot = app.add_subcommand(
      "robot", "Emulate a real robot on a pseudo-terminal (for rb run --real --port without a robot)");
  if (!withOptions) return;
  robot->add_flag("--pty", opts->pty,
                  "Open a pseudo-terminal, print its path on the first line and answer the robot "
                  "protocol on it until killed");
  robot->add_option("--link", opts->link,
                    "Also make a symbolic link PATH to the pseudo-terminal (removed at exit), e.g. "
                    "/tmp/robot for --port /tmp/robot");
  robot->add_option("--slip", opts->emulator.slipPercent,
                    "Random error of up to PERCENT in every move and turn, as rSlip")
      ->check(CLI::Range(0.0, 100.0));
  robot->add_option("--latency", opts->latencyMs, "Wait MS milliseconds before each answer")
      ->check(CLI::NonNegativeNumber);
  robot->add_option("--drop-every", opts->emulator.dropEvery, "Never answer every N-th command");
  robot->add_option("--garble-every", opts->emulator.garbleEvery,
                    "Answer every N-th command with seven bytes of 0xff");
  robot->add_option("--short-every", opts->emulator.shortEvery,
                    "Answer every N-th command with only two bytes");
  robot->add_option("--die-after", opts->emulator.dieAfter,
                    "Close the pseudo-terminal after answering N commands, then exit");
  robot->add_option("--seed", opts->emulator.seed, "Seed for --slip (default 1)");
  robot->add_flag("--verbose", opts->verbose, "Log every command and answer on stderr");
  robot->footer(
      "Between clients the emulator keeps serving: every rb run may connect in turn. Code 3 "
      "(rLocate) puts the robot back at (400, 300) facing up. Exit status: 0 stopped by a signal "
      "or --die-after, 64 bad usage, 74 no pseudo-terminal.");
  robot->callback([opts, &exitCode] { exitCode = executeRobot(*opts); });
}

}  // namespace rb::cli
