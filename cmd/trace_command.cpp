#include "trace_command.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "exit_codes.h"
#include "headless_run.h"
#include "png_writer.h"
#include "run_command.h"
#include "trace_writer.h"

namespace rb::cli {

namespace {

namespace fs = std::filesystem;

struct TraceOptions {
  std::vector<std::string> files;
  run::RunOptions run;
  std::string format = "text";
  std::string outDir;
  bool sensors = false;
  bool lines = false;
};

std::string extensionFor(const std::string& format) {
  return format == "jsonl" ? ".jsonl" : format == "csv" ? ".csv" : ".trace";
}

/// Traces one program into `out`; returns rb run's exit code for it.
int traceOne(const TraceOptions& opts, const std::string& file, std::FILE* out, const std::string& program,
             bool csvHeader) {
  TraceOptions one = opts;
  one.run.file = file;
  one.run.confined = true;  // executeTrace confined the process for every file
  run::HeadlessRun run;
  record::TraceWriter writer(
      record::TraceSettings{opts.format, opts.sensors, opts.lines}, out, program, csvHeader,
      [&run]() -> const SourceSet* { return run.loaded.program ? &run.loaded.program->sources : nullptr; },
      [&run]() -> const Machine* { return run.machine.get(); });
  CompileOptions compile;
  compile.lineTracing = true;  // to know the line of each output (and for --lines)
  int code = run::runHeadless("rb trace", one.run, compile, nullptr, &writer, run,
                              [&](SourceLoc loc) { writer.line(loc); },
                              [&](std::string_view text) { writer.output(text); });
  record::TraceEnd end;
  end.exit = code;
  if (run.ran) {
    end.result = &run.result;
    end.stepLimitIsError = run.stepLimitIsError;
    end.steps = run::countedSteps(run.result, writer.statements());
  } else if (run.loaded.program && !run.loaded.compiled) {
    end.loadErrors = &run.loaded.diags;
  } else {
    end.notRun = code == run::exitcode::kNoInput ? "cannot read '" + file + "': no such file"
                                            : "the program did not run (see standard error)";
  }
  writer.end(end);
  std::fflush(out);
  return code;
}

int executeTrace(const TraceOptions& opts) {
  bool several = opts.files.size() > 1;
  if (!opts.outDir.empty()) {
    std::map<std::string, std::string> names;
    for (const std::string& f : opts.files) {
      std::string name = fs::path(f).stem().string() + extensionFor(opts.format);
      if (auto [it, fresh] = names.emplace(name, f); !fresh) {
        std::fprintf(stderr, "rb trace: '%s' and '%s' would both be traced to %s; trace them separately\n",
                     it->second.c_str(), f.c_str(), name.c_str());
        return run::exitcode::kUsage;
      }
    }
    std::string error;
    if (!render::makeFolder(opts.outDir, error)) {
      std::fprintf(stderr, "rb trace: %s\n", error.c_str());
      return run::exitcode::kIoError;
    }
  }
  // One process traces every file: the kernel's rules cover all their folders, once.
  if (!opts.files.empty()) {
    run::RunOptions first = opts.run;
    first.file = opts.files[0];
    std::vector<std::string> outputs;
    if (!opts.outDir.empty()) outputs.push_back((fs::path(opts.outDir) / "trace").string());
    run::KernelRules rules = run::runKernelRules(first, outputs);
    std::error_code ec;
    for (const std::string& f : opts.files)
      rules.writeDirs.push_back(f == "-" ? fs::current_path(ec).string() : fs::absolute(f, ec).parent_path().string());
    run::KernelStatus status = run::confineProcess(rules);
    if (!status.complete() && opts.run.requireSandbox) {
      std::fprintf(stderr, "rb trace: --require-sandbox: the kernel cannot confine this run: %s\n", status.problem.c_str());
      return run::exitcode::kRuntime;
    }
  }
  int result = run::exitcode::kOk;
  for (size_t i = 0; i < opts.files.size(); ++i) {
    const std::string& file = opts.files[i];
    int code;
    if (!opts.outDir.empty()) {
      fs::path path = fs::path(opts.outDir) / (fs::path(file).stem().string() + extensionFor(opts.format));
      std::FILE* out = std::fopen(path.c_str(), "wb");
      if (!out) {
        std::fprintf(stderr, "rb trace: cannot write '%s'\n", path.c_str());
        return run::exitcode::kIoError;
      }
      code = traceOne(opts, file, out, "", true);
      bool failed = std::ferror(out) != 0;
      if (std::fclose(out) != 0 || failed) {
        std::fprintf(stderr, "rb trace: cannot write '%s'\n", path.c_str());
        return run::exitcode::kIoError;
      }
    } else {
      if (several && opts.format == "text") std::printf("%s==> %s <==\n", i ? "\n" : "", file.c_str());
      code = traceOne(opts, file, stdout, several && opts.format != "text" ? file : "", i == 0);
    }
    if (result == run::exitcode::kOk) result = code;
  }
  if (std::ferror(stdout)) {
    std::fprintf(stderr, "rb trace: cannot write to standard output\n");
    return run::exitcode::kIoError;
  }
  return result;
}

}  // namespace

void addTraceCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<TraceOptions>();
  CLI::App* trace = app.add_subcommand(
      "trace", "Run programs headless and print what the robot did, one line per event");
  if (!withOptions) return;
  trace->add_option("files", opts->files, "Program files (- reads standard input)")->required();
  addRunLimitOptions(*trace, opts->run);
  trace->add_option("--format", opts->format, "text, jsonl (one JSON object per line) or csv")
      ->check(CLI::IsMember({"text", "jsonl", "csv"}));
  trace->add_option("--out", opts->outDir,
                    "Write each program's trace to DIR/NAME.trace (.jsonl, .csv) instead of "
                    "standard output")
      ->type_name("DIR");
  trace->add_flag("--sensors", opts->sensors, "Also list every sensor reading with its value");
  trace->add_flag("--lines", opts->lines, "Also list every statement executed (like TRON)");
  trace->footer(
      "Each line: sequence number, source line, command and arguments, then the robot's pose "
      "after it (x, y, heading in degrees) and its pen. What the program prints is an output "
      "event with its line; the last record (end) says how the run ended: finished, error "
      "(file:line:col and message), limit, rejected or not-run, with the steps and the final "
      "pose. Several files: one stream after another (each record names its program), or one "
      "file each with --out. Exit status as for rb run (of the first program that failed). "
      "Manual: man rb-trace.");
  trace->callback([opts, &exitCode] { exitCode = executeTrace(*opts); });
}

}  // namespace rb::cli
