#include "program_run.h"

#include <filesystem>
#include <random>

#include "diagnostic_output.h"
#include "exit_codes.h"
#include "files.h"
#include "port_names.h"
#include "robot_port.h"

namespace rb::run {

int loadForRun(const char* command, const RunOptions& opts, const CompileOptions& compile,
               LoadedFile& loaded) {
  loaded = loadFile(opts.file, compile, false, false, opts.allowFiles);
  if (loaded.exitCode == exitcode::kNoInput) {
    std::fprintf(stderr, "%s: cannot read '%s': %s\n", command, opts.file.c_str(),
                 loaded.readError.c_str());
    return exitcode::kNoInput;
  }
  bool color = diagnostics::useColor(opts.color, stderr);
  if (!loaded.compiled) {
    diagnostics::DiagOutputOptions out;
    out.color = color;
    diagnostics::DiagnosticReport report(stderr, out);
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

uint64_t dataLimitBytes(uint64_t maxMemoryMiB) {
  if (maxMemoryMiB == 0) return 0;
  return (maxMemoryMiB + maxMemoryMiB / 4 + 256) << 20;
}

KernelRules runKernelRules(const RunOptions& opts, const std::vector<std::string>& outputs) {
  namespace fs = std::filesystem;
  KernelRules rules;
  std::error_code ec;
  fs::path home = opts.file == "-" ? fs::current_path(ec) : fs::absolute(opts.file, ec).parent_path();
  rules.writeDirs.push_back(home.string());
  for (const std::string& dir : opts.allowFiles) rules.writeDirs.push_back(fs::absolute(dir, ec).string());
  rules.readPaths = libraryDirs();
  if (!opts.eventsFile.empty()) rules.readPaths.push_back(fs::absolute(opts.eventsFile, ec).string());
  if (!opts.noPorts) {
    rules.devices = serialDevicePaths();
    if (!opts.port.empty()) {
      try {
        rules.devices.push_back(drivers::resolvePortOption(opts.port));
      } catch (const RuntimeError&) {
        // No such port: opening it says so.
      }
    }
  }
  for (const std::string& out : outputs) {
    if (out.empty()) continue;
    // A FIFO or a device (-o /dev/stdout) is written as it is: that one file, never its folder.
    fs::file_status st = fs::status(out, ec);
    if (fs::exists(st) && !fs::is_regular_file(st)) rules.outputFiles.push_back(out);
    else rules.outputDirs.push_back(fs::absolute(out, ec).parent_path().string());
  }
  rules.allowSpawn = opts.allowSpawn;
  rules.dataBytes = dataLimitBytes(opts.maxMemoryMiB);
  return rules;
}

std::string confineRun(const char* command, const RunOptions& opts, const std::vector<std::string>& outputs) {
  if (opts.confined) return "";
  KernelStatus status = confineProcess(runKernelRules(opts, outputs));
  if (status.complete() || !opts.requireSandbox) return "";
  return std::string(command) + ": --require-sandbox: the kernel cannot confine this run: " + status.problem;
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
    printDiagnostic(stderr, loaded.program->sources, *result.error, diagnostics::useColor(opts.color, stderr));
    return exitcode::kRuntime;
  }
  return exitcode::kOk;
}

}  // namespace rb::run
