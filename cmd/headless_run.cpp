#include "headless_run.h"

#include <iostream>
#include <random>

#include "exit_codes.h"
#include "robot_port.h"

namespace rb::cli {

int runHeadless(const char* command, const RunOptions& opts, const CompileOptions& compile,
                std::FILE* programOutput, RobotObserver* observer, HeadlessRun& run,
                std::function<void(SourceLoc)> onLine) {
  run.loaded = loadFile(opts.file, compile, false);
  if (run.loaded.exitCode == exitcode::kNoInput) {
    std::fprintf(stderr, "%s: cannot read '%s': no such file\n", command, opts.file.c_str());
    return exitcode::kNoInput;
  }
  printDiagnostics(stderr, run.loaded.program->sources, run.loaded.diags, true);
  if (!run.loaded.compiled) return exitcode::kRejected;

  run.seed = opts.seed ? *opts.seed : std::random_device{}();
  run.host = std::make_unique<HeadlessHost>(programOutput, std::cin);
  run.host->lineHook = std::move(onLine);
  run.host->robotOpener = [&opts](int64_t port) { return openRobotPort(port, opts); };
  run.machine = std::make_unique<Machine>(*run.host, run.seed);
  run.machine->setObserver(observer);
  if (opts.real) {
    try {
      run.machine->useCommPort(-1);  // -1: the port --port names
    } catch (const RuntimeError& e) {
      std::fprintf(stderr, "%s: %s\n", command, e.what());
      return exitcode::kIoError;
    }
  }
  Interpreter interp(*run.loaded.compiled, *run.machine);
  RunLimits limits;
  limits.maxSteps = opts.maxSteps;
  limits.timeoutSeconds = opts.timeoutSeconds;
  run.result = interp.run(limits);
  run.ran = true;
  run.host->flush();
  if (!opts.seed && run.machine->rngUsed())
    std::fprintf(stderr, "%s: random seed %llu (repeat this run with --seed %llu)\n", command,
                 static_cast<unsigned long long>(run.seed), static_cast<unsigned long long>(run.seed));
  if (run.result.error) {
    printDiagnostic(stderr, run.loaded.program->sources, *run.result.error);
    return exitcode::kRuntime;
  }
  if (run.result.status == RunStatus::Stopped) return exitcode::kRuntime;
  return exitcode::kOk;
}

}  // namespace rb::cli
