#include "test_job.h"

#include <CLI/CLI.hpp>
#include <string>

#include "exit_codes.h"
#include "headless_run.h"
#include "lang/checker.h"
#include "png_writer.h"
#include "record.h"
#include "robot_view.h"
#include "tui_run.h"

namespace rb::cli {

namespace {

struct JobOptions {
  RunOptions run;
  std::string record;       ///< where the JSON record goes
  std::string screen;       ///< where the final screen goes ("": not wanted)
  std::string checkTarget;  ///< "rb9": also rb check --target rb9's warnings
};

grade::DiagRecord diagRecord(const SourceSet* sources, const Diagnostic& d) {
  grade::DiagRecord r;
  if (sources && d.loc.valid() && d.loc.file < sources->size()) r.file = sources->file(d.loc.file).name();
  r.line = d.loc.line;
  r.col = d.loc.col;
  r.severity = severityName(d.severity);
  r.message = d.message;
  return r;
}

/// rb check's view of the program, as `rb check [--target rb9] FILE` reports it.
void recordCheck(const JobOptions& opts, grade::RunRecord& rec) {
  LoadedFile checked = loadFile(opts.run.file, CompileOptions{}, true);
  if (checked.exitCode == exitcode::kNoInput) {
    rec.checkExit = exitcode::kNoInput;
    return;
  }
  const SourceSet* sources = &checked.program->sources;
  for (const Diagnostic& d : checked.diags.all()) rec.checkDiags.push_back(diagRecord(sources, d));
  if (opts.checkTarget == "rb9") {
    DiagnosticList extra;
    checkRb9Target(*checked.program, extra);
    extra.sort();
    for (const Diagnostic& d : extra.all()) rec.targetDiags.push_back(diagRecord(sources, d));
  }
  rec.checkExit = checked.diags.hasErrors() ? exitcode::kRejected : exitcode::kOk;
}

int executeJob(JobOptions opts) {
  opts.run.quiet = true;  // rb check's part of the record has the warnings
  grade::RunRecord rec;
  recordCheck(opts, rec);
  int code = exitcode::kOk;
  if (opts.run.tui) {
    code = runTui(opts.run);  // a job has no terminal: this reports why, as rb run --tui would
  } else {
    grade::PathRecorder recorder;
    HeadlessRun run;
    CompileOptions compile;
    compile.lineTracing = true;  // to count the statements exactly, up to a runtime error
    uint64_t started = 0;
    code = runHeadless("rb run", opts.run, compile, stdout, &recorder, run, [&](SourceLoc) { ++started; });
    const SourceSet* sources = run.loaded.program ? &run.loaded.program->sources : nullptr;
    if (run.loaded.program && !run.loaded.compiled) {
      rec.status = "rejected";
      for (const Diagnostic& d : run.loaded.diags.all())
        if (d.severity == Severity::Error) rec.loadErrors.push_back(diagRecord(sources, d));
    } else if (run.ran) {
      rec.status = grade::statusName(run.result.status);
      rec.limit = grade::limitName(run.result.status);
      if (run.result.error) rec.error = diagRecord(sources, *run.result.error);
      rec.steps = countedSteps(run.result, started);
      rec.seed = run.seed;
      rec.located = run.machine->robot().located();
      const Pose& pose = run.machine->robot().pose();
      rec.pos = {pose.pos.x(), pose.pos.y()};
      rec.heading = pose.heading;
      rec.penDown = run.machine->robot().penDown();
      rec.crashed = recorder.crashed;
      rec.path = std::move(recorder.path);
      rec.trail = std::move(recorder.trail);
      rec.truncated = recorder.truncated;
      if (!opts.screen.empty()) {
        const Machine& m = *run.machine;
        std::string error;
        rec.screen = grade::writeScreenFile(
            opts.screen, render::composeImage(m.canvas().pixels(), render::robotView(m), 1), error);
        if (!rec.screen) std::fprintf(stderr, "rb test-job: %s\n", error.c_str());
      }
    }
  }
  rec.exitCode = code;
  std::string json = grade::recordToJson(rec), error;
  if (!render::writeFileBytes(opts.record, json.data(), json.size(), error)) {
    std::fprintf(stderr, "rb test-job: %s\n", error.c_str());
    return exitcode::kIoError;
  }
  return code;
}

}  // namespace

void addTestJobCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<JobOptions>();
  CLI::App* job = app.add_subcommand(kTestJobCommand, "Run one program for rb test (internal)");
  job->group("");  // hidden from rb --help
  if (!withOptions) return;
  job->add_option("file", opts->run.file, "Program file")->required();
  addRunLimitOptions(*job, opts->run);
  job->add_flag("--tui", opts->run.tui, "As rb run --tui");
  job->add_option("--cells", opts->run.cells, "As rb run --cells");
  job->add_option("--record", opts->record, "Where to write the JSON record of the run")->required();
  job->add_option("--screen", opts->screen, "Where to write the final screen (binary PPM)");
  job->add_option("--check-target", opts->checkTarget, "Also record rb check --target's warnings")
      ->check(CLI::IsMember({"rb9"}));
  job->callback([opts, &exitCode] { exitCode = executeJob(*opts); });
}

}  // namespace rb::cli
