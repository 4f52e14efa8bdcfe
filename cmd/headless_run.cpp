#include "headless_run.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <random>

#include "diagnostic_output.h"
#include "exit_codes.h"
#include "files.h"
#include "robot_port.h"

namespace rb::cli {

int loadInputScript(const char* command, const RunOptions& opts, InputScript& script) {
  script = InputScript{};
  bool events = !opts.eventsFile.empty(), keys = !opts.keys.empty();
  if (!events && !keys) return exitcode::kOk;
  script.given = true;
  script.origin = events && keys ? "the --events script and --keys text"
                  : events      ? "the --events script"
                                : "the --keys text";
  if (events) {
    std::string why;
    std::optional<std::string> text = readFile(opts.eventsFile, &why);
    if (!text) {
      std::fprintf(stderr, "%s: cannot read events file '%s': %s\n", command,
                   opts.eventsFile.c_str(), why.c_str());
      return exitcode::kNoInput;
    }
    script.eventsFile = opts.eventsFile;
    try {
      script.steps = parseEventScript(*text);
    } catch (const ScriptError& e) {
      std::fprintf(stderr, "%s: %s:%d: %s\n", command, opts.eventsFile.c_str(), e.line, e.what());
      return exitcode::kUsage;
    }
  }
  if (keys) {
    try {
      for (ScriptStep& s : parseKeyText(opts.keys)) script.steps.push_back(std::move(s));
    } catch (const ScriptError& e) {
      std::fprintf(stderr, "%s: --keys: %s\n", command, e.what());
      return exitcode::kUsage;
    }
  }
  return exitcode::kOk;
}

int loadForRun(const char* command, const RunOptions& opts, const CompileOptions& compile,
               LoadedFile& loaded) {
  loaded = loadFile(opts.file, compile, false);
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
  RunLimits limits;
  limits.maxSteps = opts.maxSteps;
  limits.timeoutSeconds = opts.timeoutSeconds;
  return limits;
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

uint64_t countedSteps(const RunResult& result, uint64_t started) {
  if (result.status == RunStatus::StepLimit) return result.steps;
  return std::max(result.steps, started);
}

int runHeadless(const char* command, const RunOptions& opts, const CompileOptions& compile,
                std::FILE* programOutput, RobotObserver* observer, HeadlessRun& run,
                std::function<void(SourceLoc)> onLine,
                std::function<void(std::string_view)> onOutput) {
  if (int code = loadForRun(command, opts, compile, run.loaded)) return code;

  InputScript script;
  if (int code = loadInputScript(command, opts, script)) return code;

  run.seed = runSeed(opts);
  run.host = std::make_unique<HeadlessHost>(programOutput, std::cin, std::move(script));
  run.host->lineHook = std::move(onLine);
  run.host->outputHook = std::move(onOutput);
  run.host->robotOpener = [&opts](int64_t port) { return openRobotPort(port, opts); };
  run.sandbox = runSandbox(opts);
  run.host->setSystem(run.sandbox.get());
  run.machine = std::make_unique<Machine>(*run.host, run.seed);
  run.machine->setObserver(observer);
  run.machine->canvas().keepDisplayList(run.keepDisplayList);
  if (std::string why = connectRealRobot(opts, *run.machine); !why.empty()) {
    std::fprintf(stderr, "%s: %s\n", command, why.c_str());
    return exitcode::kIoError;
  }
  Interpreter interp(*run.loaded.compiled, *run.machine);
  run.result = interp.run(runLimits(opts));
  run.ran = true;
  run.host->flush();
  if (int err = run.host->writeError()) {
    std::fprintf(stderr, "%s: cannot write the program's output: %s\n", command, std::strerror(err));
    return exitcode::kIoError;
  }
  reportSeed(command, opts, run.seed, *run.machine);
  if (run.result.status == RunStatus::StepLimit && !run.stepLimitIsError) return exitcode::kOk;
  if (run.result.error) {
    printDiagnostic(stderr, run.loaded.program->sources, *run.result.error, useColor(opts.color, stderr));
    return exitcode::kRuntime;
  }
  if (run.result.status == RunStatus::Stopped) return exitcode::kRuntime;
  return exitcode::kOk;
}

}  // namespace rb::cli
