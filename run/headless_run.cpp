#include "headless_run.h"

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <iostream>

#include "diagnostic_output.h"
#include "exit_codes.h"
#include "files.h"
#include "robot_port.h"

namespace rb::run {

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

uint64_t countedSteps(const RunResult& result, uint64_t started) {
  if (result.status == RunStatus::StepLimit) return result.steps;
  return std::max(result.steps, started);
}

int runHeadless(const char* command, const RunOptions& opts, const CompileOptions& compile,
                std::FILE* programOutput, RobotObserver* observer, HeadlessRun& run,
                std::function<void(SourceLoc)> onLine,
                std::function<void(std::string_view)> onOutput) {
  // The kernel's rules first: the program and its includes are read under them too.
  if (!run.memory) run.memory = std::make_shared<ResidentMemory>();
  if (std::string why = confineRun(command, opts, run.outputs); !why.empty()) {
    std::fprintf(stderr, "%s\n", why.c_str());
    return exitcode::kRuntime;
  }
  if (int code = run.load(command, opts, compile)) return code;

  InputScript script;
  if (int code = loadInputScript(command, opts, script)) return code;

  auto host = std::make_unique<HeadlessHost>(programOutput, std::cin, std::move(script));
  host->inputFd = STDIN_FILENO;
  host->memory = run.memory;
  // A terminal shows what the user typed; a pipe or a file shows nothing, so rb writes it.
  host->echoInput = !::isatty(STDIN_FILENO);
  host->inputHook = run.onInput;
  host->copyHook = run.onCopy;
  host->lineHook = std::move(onLine);
  host->outputHook = std::move(onOutput);
  host->robotOpener = [&opts](int64_t port) { return openRobotPort(port, opts); };
  if (std::string why = run.start(opts, std::move(host), observer); !why.empty()) {
    std::fprintf(stderr, "%s: %s\n", command, why.c_str());
    return exitcode::kIoError;
  }
  if (run.beforeRun) {
    if (std::string why = run.beforeRun(run); !why.empty()) {
      run.headlessHost().flush();
      std::fprintf(stderr, "%s: %s\n", command, why.c_str());
      return exitcode::kRuntime;
    }
  }
  run.run(opts);
  if (run.afterRun) run.afterRun(run);
  run.headlessHost().flush();
  if (int err = run.headlessHost().writeError()) {
    std::fprintf(stderr, "%s: cannot write the program's output: %s\n", command, std::strerror(err));
    return exitcode::kIoError;
  }
  // The host stops a run only when output could not be written (reported above).
  return run.conclude(command, opts, exitcode::kRuntime);
}

}  // namespace rb::run
