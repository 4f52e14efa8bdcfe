#include "run_command.h"

#include <cstdio>
#include <iostream>
#include <random>

#include "exit_codes.h"
#include "headless_host.h"
#include "interpreter.h"
#include "machine.h"
#include "program_loader.h"

namespace rb::cli {

void addRunLimitOptions(CLI::App& app, RunOptions& opts) {
  app.add_option("--seed", opts.seed,
                 "Seed for random numbers and rSlip (default: a random seed, reported on stderr "
                 "when the program uses it)");
  app.add_option("--max-steps", opts.maxSteps,
                 "Stop the program after N statements (0: no limit)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--timeout", opts.timeoutSeconds,
                 "Stop the program after SECONDS of real time (0: no limit)")
      ->check(CLI::NonNegativeNumber);
}

namespace {

int executeRun(const RunOptions& opts) {
  LoadedFile loaded = loadFile(opts.file, CompileOptions{}, false);
  if (loaded.exitCode == exitcode::kNoInput) {
    std::fprintf(stderr, "rb run: cannot read '%s': no such file\n", opts.file.c_str());
    return exitcode::kNoInput;
  }
  printDiagnostics(stderr, loaded.program->sources, loaded.diags, true);
  if (!loaded.compiled) return exitcode::kRejected;

  uint64_t seed = opts.seed ? *opts.seed : std::random_device{}();
  HeadlessHost host(stdout, std::cin);
  Machine machine(host, seed);
  Interpreter interp(*loaded.compiled, machine);
  RunLimits limits;
  limits.maxSteps = opts.maxSteps;
  limits.timeoutSeconds = opts.timeoutSeconds;
  RunResult result = interp.run(limits);
  host.flush();
  if (!opts.seed && machine.rngUsed())
    std::fprintf(stderr, "rb run: random seed %llu (repeat this run with --seed %llu)\n",
                 static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed));
  if (result.error) {
    printDiagnostic(stderr, loaded.program->sources, *result.error);
    return exitcode::kRuntime;
  }
  if (result.status == RunStatus::Stopped) return exitcode::kRuntime;
  return exitcode::kOk;
}

}  // namespace

void addRunCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand("run", "Run a RobotBASIC program (headless on the simulator)");
  run->add_option("file", opts->file, "Program file (- reads the program from standard input)")
      ->required();
  addRunLimitOptions(*run, *opts);
  run->footer(
      "Exit status: 0 finished, 64 bad usage, 65 the program has errors (nothing ran), "
      "66 file not found, 70 runtime error or limit reached, 74 I/O error.");
  run->callback([opts, &exitCode] { exitCode = executeRun(*opts); });
}

}  // namespace rb::cli
