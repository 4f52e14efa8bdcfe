#include "program_run.h"

#include <filesystem>
#include <random>

#include "diagnostic_output.h"
#include "exit_codes.h"
#include "robot_port.h"

namespace rb::cli {

int loadForRun(const char* command, const RunOptions& opts, const CompileOptions& compile,
               LoadedFile& loaded) {
  loaded = loadFile(opts.file, compile, false, false, opts.allowFiles);
  if (loaded.exitCode == exitcode::kNoInput) {
    std::fprintf(stderr, "%s: cannot read '%s': %s\n", command, opts.file.c_str(),
                 loaded.readError.c_str());
    return exitcode::kNoInput;
  }
  bool color = useColor(opts.color, stderr);
  if (!loaded.compiled) {
    DiagOutputOptions out;
    out.color = color;
    DiagnosticReport report(stderr, out);
    report.add(loaded.program->sources, loaded.diags, true);
    report.finish();
    return exitcode::kRejected;
  }
  if (!opts.quiet) printWarningLines(command, opts.file, loaded.program->sources, loaded.diags, color);
  return exitcode::kOk;
}

uint64_t runSeed(const RunOptions& opts) { return opts.seed ? *opts.seed : std::random_device{}(); }

RunLimits runLimits(const RunOptions& opts) {
  return RunLimits::of(opts.maxSteps, opts.timeoutSeconds, opts.maxMemoryMiB);
}

std::unique_ptr<Sandbox> runSandbox(const RunOptions& opts) {
  std::string home = opts.file == "-" ? "." : std::filesystem::path(opts.file).parent_path().string();
  return std::make_unique<Sandbox>(home.empty() ? "." : home, opts.allowFiles, opts.allowSpawn);
}

std::string connectRealRobot(const RunOptions& opts, Machine& machine) {
  if (!opts.real) return "";
  try {
    machine.connectRobot(openRobotPort(std::nullopt, opts));  // the port --port names
  } catch (const RuntimeError& e) {
    return e.what();
  }
  return "";
}

void reportSeed(const char* command, const RunOptions& opts, uint64_t seed, const Machine& machine) {
  if (!opts.seed && machine.rngUsed())
    std::fprintf(stderr, "%s: random seed %llu (repeat this run with --seed %llu)\n", command,
                 static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed));
}

int ProgramRun::load(const char* command, const RunOptions& opts, const CompileOptions& compile) {
  return loadForRun(command, opts, compile, loaded);
}

std::string ProgramRun::start(const RunOptions& opts, std::unique_ptr<Host> runHost,
                              RobotObserver* observer) {
  seed = runSeed(opts);
  host = std::move(runHost);
  sandbox = runSandbox(opts);
  host->setSystem(sandbox.get());
  machine = std::make_unique<Machine>(*host, seed);
  machine->setObserver(observer);
  machine->canvas().keepDisplayList(keepDisplayList);
  host->attachMachine(*machine);
  interpreter = std::make_unique<Interpreter>(*loaded.compiled, *machine);
  return connectRealRobot(opts, *machine);
}

void ProgramRun::run(const RunOptions& opts) {
  result = interpreter->run(runLimits(opts));
  ran = true;
}

int ProgramRun::conclude(const char* command, const RunOptions& opts, int stoppedCode) const {
  reportSeed(command, opts, seed, *machine);
  if (result.status == RunStatus::Stopped) return stoppedCode;
  if (result.status == RunStatus::StepLimit && !stepLimitIsError) return exitcode::kOk;
  if (result.error) {
    printDiagnostic(stderr, loaded.program->sources, *result.error, useColor(opts.color, stderr));
    return exitcode::kRuntime;
  }
  return exitcode::kOk;
}

}  // namespace rb::cli
