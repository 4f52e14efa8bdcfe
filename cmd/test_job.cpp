#include "test_job.h"

#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <stdio_ext.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>

#include "animation.h"
#include "colour_watch.h"
#include "run_command.h"
#include "exit_codes.h"
#include "headless_run.h"
#include "lang/checker.h"
#include "lang/portable_check.h"
#include "png_writer.h"
#include "record.h"
#include "robot_view.h"
#include "tui_run.h"

namespace rb::cli {

namespace {

struct JobOptions {
  run::RunOptions run;
  std::string record;       ///< where the JSON record goes
  std::string screen;       ///< where the final screen goes ("": not wanted)
  std::string checkTarget;  ///< "rb9": also rb check --target rb9's warnings
  bool checkPortable = false;  ///< also rb check --portable's warnings
  std::string world;        ///< a program run before the student's, on the same screen
  std::vector<std::string> posts;      ///< programs run after it, on the final state
  std::vector<std::string> watch;      ///< colours (RRGGBB hex) the robot must avoid or touch
  std::string replay;                  ///< where to write the run's replay (.gif, .svg, .html), or ""
  bool ports = false;                  ///< the grader lets the program open serial ports
  /// rb test's scratch folder for this run, holding the program's copy: the only folder the
  /// program may change, by the kernel's rules. "": the program runs where it is (rb test
  /// --trust-comments), confined as rb run confines it.
  std::string box;
};

/// A file rb test handed the job to write its results in: opened before the job is confined,
/// so that neither the program nor anything it starts can reach it (it is not inherited), and
/// written whole each time.
class HandedFile {
 public:
  HandedFile() = default;
  HandedFile(const HandedFile&) = delete;
  HandedFile& operator=(const HandedFile&) = delete;
  ~HandedFile() {
    if (fd_ >= 0) ::close(fd_);
  }
  /// "" when `path` is empty (not wanted) or was opened, else why not.
  std::string open(const std::string& path) {
    path_ = path;
    if (path.empty()) return "";
    fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0600);
    return fd_ < 0 ? "cannot write '" + path + "': " + std::strerror(errno) : "";
  }
  bool wanted() const { return fd_ >= 0; }
  bool write(std::string_view bytes, std::string& error) {
    if (fd_ < 0) return false;
    if (::ftruncate(fd_, 0) != 0) {
      error = "cannot write '" + path_ + "': " + std::strerror(errno);
      return false;
    }
    size_t done = 0;
    while (done < bytes.size()) {
      ssize_t n = ::pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        error = "cannot write '" + path_ + "': " + std::strerror(n < 0 ? errno : EIO);
        return false;
      }
      done += static_cast<size_t>(n);
    }
    return true;
  }

 private:
  int fd_ = -1;
  std::string path_;
};

/// The kernel's rules for the job (kernel_confine.h): rb run's, but in its scratch folder that
/// folder alone to change; never root's capabilities.
run::KernelRules jobRules(const JobOptions& opts) {
  run::KernelRules rules = run::runKernelRules(opts.run);
  std::error_code ec;
  if (!opts.box.empty()) rules.writeDirs = {std::filesystem::absolute(opts.box, ec).string()};
  rules.dropCapabilities = true;
  return rules;
}

record::DiagRecord diagRecord(const SourceSet* sources, const Diagnostic& d) {
  record::DiagRecord r;
  if (sources && d.loc.valid() && d.loc.file < sources->size()) r.file = sources->file(d.loc.file).name();
  r.line = d.loc.line;
  r.col = d.loc.col;
  r.severity = severityName(d.severity);
  r.message = d.message;
  return r;
}

/// rb check's view of the program, as `rb check [--target rb9] [--portable] FILE` reports it
/// (the warnings of those options as the record's target warnings); `placed`:
/// as it runs, after a world program that placed the robot.
void recordCheck(const JobOptions& opts, record::RunRecord& rec, bool placed = false) {
  LintOptions lint;
  lint.realRobot = opts.checkTarget == "rb9";  // a real robot needs no rLocate
  lint.robotPlaced = placed;
  rec.checkDiags.clear();
  rec.targetDiags.clear();
  run::LoadedFile checked = run::loadFile(opts.run.file, CompileOptions{}, true, false, opts.run.allowFiles, lint);
  if (checked.exitCode == run::exitcode::kNoInput) {
    rec.checkExit = run::exitcode::kNoInput;
    return;
  }
  const SourceSet* sources = &checked.program->sources;
  for (const Diagnostic& d : checked.diags.all()) rec.checkDiags.push_back(diagRecord(sources, d));
  if (opts.checkTarget == "rb9" || opts.checkPortable) {
    DiagnosticList extra;
    if (opts.checkTarget == "rb9") checkRb9Target(*checked.program, extra);
    if (opts.checkPortable) checkPortable(*checked.program, extra);
    extra.sort();
    for (const Diagnostic& d : extra.all()) rec.targetDiags.push_back(diagRecord(sources, d));
  }
  rec.checkExit = checked.diags.hasErrors() ? run::exitcode::kRejected : run::exitcode::kOk;
}

bool writeRecord(HandedFile& file, const record::RunRecord& rec) {
  std::string json = record::recordToJson(rec), error;
  if (file.write(json, error)) return true;
  std::fprintf(stderr, "rb test-job: %s\n", error.c_str());
  return false;
}

/// The innermost loop of the main file around `at`: for/next, while/wend, repeat/until, or a
/// label with a later goto back to it. {0, 0} when none.
std::pair<uint32_t, uint32_t> loopAround(const LoadedProgram& program, SourceLoc at) {
  std::pair<uint32_t, uint32_t> best{0, 0};
  if (!at.valid() || at.file != 0) return best;
  auto consider = [&](uint32_t first, uint32_t last) {
    if (first <= at.line && at.line <= last &&
        (best.first == 0 || last - first < best.second - best.first))
      best = {first, last};
  };
  std::vector<uint32_t> open;
  std::vector<std::pair<std::string_view, uint32_t>> labels;
  auto jumpBack = [&](const ast::Stmt& s) {
    if (s.kind != ast::StmtKind::Goto) return;
    for (const auto& [name, line] : labels)
      if (name == s.name && line <= s.loc.line) consider(line, s.loc.line);
  };
  ast::Arena scratch;
  ast::StmtCursor cursor = program.cursor(scratch);
  while (!cursor.done()) {
    const ast::Stmt* s = cursor.next();
    if (!s || s->loc.file != 0) continue;
    switch (s->kind) {
      case ast::StmtKind::For:
      case ast::StmtKind::While:
      case ast::StmtKind::Repeat: open.push_back(s->loc.line); break;
      case ast::StmtKind::Next:
      case ast::StmtKind::Wend:
      case ast::StmtKind::Until:
        if (!open.empty()) {
          consider(open.back(), s->loc.line);
          open.pop_back();
        }
        break;
      case ast::StmtKind::Label: labels.push_back({s->name, s->loc.line}); break;
      case ast::StmtKind::Goto: jumpBack(*s); break;
      case ast::StmtKind::IfLine:
        for (const ast::Stmt* b : s->body)
          if (b) jumpBack(*b);
        break;
      default: break;
    }
  }
  return best;
}

/// Passes every robot event on to the path recorder, the colour watch (when the grader watches
/// colours) and the replay's recording.
class JobObserver : public RobotObserver {
 public:
  JobObserver(const std::vector<uint32_t>& colours, Machine& machine) : machine_(machine) {
    if (!colours.empty()) watch.emplace(machine.canvas(), colours);
  }

  void robotEvent(const RobotEvent& e) override {
    if (watch) watch->robotEvent(e, machine_.robot().radius());
    recorder.robotEvent(e);
    if (recording) recording->robotEvent(e);
  }

  /// The replay's recording, when one is asked for.
  Recording* recording = nullptr;

  /// Where the robot is when the student's program starts (a world program may have placed it):
  /// the path starts there, without counting as the student's move.
  void startAt(const Robot& robot) {
    if (!robot.located()) return;
    RobotEvent e{RobotEvent::Locate, "rLocate", {}, "", robot.pose(), robot.penDown(), std::nullopt};
    recorder.robotEvent(e);
    recorder.moves = 0;
    if (watch) watch->startAt({e.pose.pos.x(), e.pose.pos.y()});
  }

  record::PathRecorder recorder;
  std::optional<record::ColourWatch> watch;

 private:
  Machine& machine_;
};

/// A teacher's program (world or post) compiled for running on the student's machine.
struct TeacherProgram {
  run::LoadedFile loaded;
  std::string problem;  ///< why it cannot run
};

TeacherProgram loadTeacherProgram(const std::string& file) {
  TeacherProgram p;
  p.loaded = run::loadFile(file, CompileOptions{}, false);
  if (p.loaded.exitCode == run::exitcode::kNoInput) {
    p.problem = "cannot read " + file + ": " + p.loaded.readError;
  } else if (!p.loaded.compiled) {
    for (const Diagnostic& d : p.loaded.diags.all())
      if (d.severity == Severity::Error) {
        record::DiagRecord r = diagRecord(&p.loaded.program->sources, d);
        p.problem = r.file + ":" + std::to_string(r.line) + ":" + std::to_string(r.col) + ": " + r.message;
        break;
      }
  }
  return p;
}

/// Runs a teacher's program on the run's machine with the run's limits. Returns its result.
RunResult runTeacherProgram(const TeacherProgram& p, run::HeadlessRun& run, const run::RunOptions& opts) {
  Interpreter interpreter(*p.loaded.compiled, *run.machine);
  return interpreter.run(run::runLimits(opts));
}

/// The record's confinement for a job run in rb's own process (rb test --in-process): the
/// kernel's rules would confine rb itself, so only rb's own hold.
constexpr const char* kInProcessConfinement =
    "each program ran inside rb's own process: rb's own rules confined it (its folder, no other "
    "programs), not the kernel's";

int executeJob(JobOptions opts, bool inProcess) {
  opts.run.quiet = true;  // rb check's part of the record has the warnings
  opts.run.noPorts = !opts.ports;
  // What the job writes for rb test, and what the teacher's programs are, is opened and read
  // before the job is confined: afterwards only the program's own folder can be reached.
  HandedFile recordFile, screenFile, replayFile;
  for (auto [file, path] : {std::pair{&recordFile, &opts.record}, {&screenFile, &opts.screen}, {&replayFile, &opts.replay}})
    if (std::string why = file->open(*path); !why.empty()) {
      std::fprintf(stderr, "rb test-job: %s\n", why.c_str());
      return run::exitcode::kIoError;
    }
  std::optional<TeacherProgram> world;
  std::vector<TeacherProgram> posts;
  if (!opts.world.empty()) world = loadTeacherProgram(opts.world);
  for (const std::string& p : opts.posts) posts.push_back(loadTeacherProgram(p));
  run::HeadlessRun run;
  run.memory = std::make_shared<run::ResidentMemory>();
  record::RunRecord rec;
  run::KernelStatus kernel;
  if (inProcess) kernel.problem = kInProcessConfinement;
  else kernel = run::confineProcess(jobRules(opts));
  opts.run.confined = true;
  rec.confinement = kernel.problem;
  if ((inProcess || !kernel.complete()) && opts.run.requireSandbox) {
    std::fprintf(stderr, "rb run: --require-sandbox: the kernel cannot confine this run: %s\n", kernel.problem.c_str());
    rec.complete = true;
    rec.exitCode = run::exitcode::kRuntime;
    writeRecord(recordFile, rec);
    return run::exitcode::kRuntime;
  }
  recordCheck(opts, rec);
  // Written now and again at the end: a run killed at its time limit keeps rb check's part.
  rec.complete = false;
  if (!writeRecord(recordFile, rec)) return run::exitcode::kIoError;
  rec.complete = true;
  int code = run::exitcode::kOk;
  if (opts.run.tui) {
    code = tui::runTui(opts.run);  // a job has no terminal: this reports why, as rb run --tui would
  } else {
    std::vector<uint32_t> colours;
    for (const std::string& hex : opts.watch) colours.push_back(static_cast<uint32_t>(std::stoul(hex, nullptr, 16)));
    std::optional<JobObserver> observer;
    std::string output;  // the student's output as it goes to stdout, for the post programs
    run.onInput = [&rec](const run::HeadlessHost::InputSpan& s) {
      if (rec.inputs.size() < 100000) rec.inputs.push_back({s.start, s.promptEnd, s.end});
    };
    std::optional<Recording> recording;
    if (replayFile.wanted()) recording.emplace();
    if (!opts.posts.empty() || recording)
      run.onCopy = [&output, &recording, keep = !opts.posts.empty()](std::string_view text) {
        if (keep && output.size() < (1u << 20)) output.append(text.substr(0, (1u << 20) - output.size()));
        if (recording) recording->output(text);
      };
    run.beforeRun = [&](run::HeadlessRun& r) -> std::string {
      observer.emplace(colours, *r.machine);
      if (world) {
        if (!world->problem.empty()) return rec.worldError = "the world program " + world->problem;
        r.machine->setObserver(nullptr);
        run::HeadlessHost& host = r.headlessHost();
        auto saved = std::move(host.outputHook);
        host.outputHook = [](std::string_view) {};  // the world's prints are not the student's
        // Nor is the student's input the world's: its `input` reads empty lines.
        host.inputSource = []() -> std::optional<std::string> { return std::string(); };
        RunResult w = runTeacherProgram(*world, r, opts.run);
        host.inputSource = nullptr;
        host.outputHook = std::move(saved);
        if (w.error) {
          record::DiagRecord d = diagRecord(&world->loaded.program->sources, *w.error);
          return rec.worldError = "the world program " + d.file + " stopped at line " +
                                  std::to_string(d.line) + ": " + d.message;
        }
        observer->startAt(r.machine->robot());
        // rb check's view as the program runs: after this world, which placed the robot.
        if (r.machine->robot().located()) {
          recordCheck(opts, rec, true);
          rec.complete = false;
          bool written = writeRecord(recordFile, rec);
          rec.complete = true;
          if (!written) return "cannot write the record";
        }
      }
      if (recording) observer->recording = &*recording;
      r.machine->setObserver(&*observer);
      return "";
    };
    std::optional<std::vector<render::ColourRun>> finalScreen;
    run.afterRun = [&](run::HeadlessRun& r) {
      r.machine->setObserver(nullptr);
      if (recording) recording->finish(*r.machine, r.result);  // before the post programs
      // The student's screen as their program left it: a post program's prints (a hidden
      // check's "fail: ...") never reach a picture, a thumbnail or a replay.
      if (screenFile.wanted())
        finalScreen = render::composeRuns(r.machine->canvas().pixels(), render::robotView(*r.machine));
      if (posts.empty()) return;
      run::HeadlessHost& host = r.headlessHost();
      host.flush();
      // What the student printed, as the post programs' input.
      host.copyHook = nullptr;
      std::vector<std::string> lines;
      std::string printed = record::printedOutput(output, rec.inputs);
      for (size_t at = 0; at < printed.size();) {
        size_t nl = std::min(printed.find('\n', at), printed.size());
        lines.push_back(printed.substr(at, nl - at));
        at = nl + 1;
      }
      for (size_t i = 0; i < posts.size(); ++i) {
        record::RunRecord::Post result;
        result.file = opts.posts[i];
        if (!posts[i].problem.empty()) {
          result.error = record::DiagRecord{opts.posts[i], 0, 0, "error", posts[i].problem};
          rec.posts.push_back(std::move(result));
          continue;
        }
        size_t next = 0;
        host.inputSource = [&]() -> std::optional<std::string> {
          return next < lines.size() ? lines[next++] : std::string();
        };
        host.outputHook = [&](std::string_view text) {
          if (result.output.size() < (64u << 10)) result.output += text;
        };
        RunResult p = runTeacherProgram(posts[i], r, opts.run);
        host.outputHook = nullptr;
        host.inputSource = nullptr;
        result.ran = true;
        if (p.error) result.error = diagRecord(&posts[i].loaded.program->sources, *p.error);
        rec.posts.push_back(std::move(result));
      }
    };
    CompileOptions compile;
    compile.lineTracing = true;  // to count the statements exactly, up to a runtime error
    uint64_t started = 0;
    code = run::runHeadless("rb run", opts.run, compile, stdout, nullptr, run, [&](SourceLoc loc) {
      ++started;
      if (recording) recording->statement(loc, *run.machine);
    });
    const SourceSet* sources = run.loaded.program ? &run.loaded.program->sources : nullptr;
    if (run.loaded.program) rec.statements = run.loaded.program->stmtCount();
    if (run.loaded.program && !run.loaded.compiled) {
      rec.status = "rejected";
      for (const Diagnostic& d : run.loaded.diags.all())
        if (d.severity == Severity::Error) rec.loadErrors.push_back(diagRecord(sources, d));
    } else if (run.ran) {
      rec.status = record::statusName(run.result.status);
      rec.limit = record::limitName(run.result.status);
      if (run.result.error) {
        rec.error = diagRecord(sources, *run.result.error);
        if (!rec.limit.empty()) {
          auto [first, last] = loopAround(*run.loaded.program, run.result.error->loc);
          rec.loopFirst = first;
          rec.loopLast = last;
        }
      }
      rec.steps = run::countedSteps(run.result, started);
      rec.seed = run.seed;
      rec.located = run.machine->robot().located();
      const Pose& pose = run.machine->robot().pose();
      rec.pos = {pose.pos.x(), pose.pos.y()};
      rec.heading = pose.heading;
      rec.penDown = run.machine->robot().penDown();
      rec.radius = run.machine->robot().radius();
      if (observer) {
        record::PathRecorder& recorder = observer->recorder;
        rec.crashed = recorder.crashed;
        rec.moves = recorder.moves;
        rec.path = std::move(recorder.path);
        rec.pathLines = std::move(recorder.pathLines);
        rec.trail = std::move(recorder.trail);
        rec.truncated = recorder.truncated;
        if (observer->watch) rec.touches = observer->watch->touches();
      }
      if (recording && recording->finished()) {
        const SourceFile& main = run.loaded.program->sources.file(0);
        render::PlayerSource source{std::filesystem::path(main.name()).filename().string(), main.text(), 0};
        std::string error;
        try {
          // The report's replays play once they come into view (docs/teaching.md).
          render::AnimationOptions replayOptions;
          replayOptions.autoplay = true;
          std::string bytes = render::encodeAnimation(render::animationFormat(opts.replay), *recording, source,
                                                      replayOptions);
          if (!replayFile.write(bytes, error)) std::fprintf(stderr, "rb test-job: %s\n", error.c_str());
        } catch (const std::exception& e) {
          std::fprintf(stderr, "rb test-job: cannot make the replay: %s\n", e.what());
        }
      }
      if (screenFile.wanted() && finalScreen) {
        std::string error;
        std::string bytes = record::screenFileBytes(*finalScreen, Canvas::kWidth, Canvas::kHeight);
        rec.screen = screenFile.write(bytes, error);
        if (!rec.screen) std::fprintf(stderr, "rb test-job: %s\n", error.c_str());
      }
    }
  }
  rec.exitCode = code;
  if (!writeRecord(recordFile, rec)) return run::exitcode::kIoError;
  return code;
}

}  // namespace

namespace {

void addJobCommand(CLI::App& app, int& exitCode, bool withOptions, bool inProcess) {
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
  job->add_flag("--check-portable", opts->checkPortable, "Also record rb check --portable's warnings");
  job->add_option("--world", opts->world, "A program run first, on the same screen");
  job->add_option("--post", opts->posts, "A program run after, on the final state; repeatable");
  job->add_option("--watch-colour", opts->watch, "A colour (RRGGBB) to record touches of; repeatable");
  job->add_option("--replay", opts->replay, "Write the run's replay here (.gif, .svg or .html)");
  job->add_flag("--ports,!--no-ports", opts->ports, "Let the program open serial ports (default: not)");
  job->add_option("--box", opts->box, "rb test's scratch folder for this run: the only folder the program may change");
  job->callback([opts, &exitCode, inProcess] { exitCode = executeJob(*opts, inProcess); });
}

/// The job's standard input, output and error and its working folder, set in this process for
/// the time of one job and put back after it.
class JobStreams {
 public:
  explicit JobStreams(const grade::Job& job) {
    std::fflush(stdout);
    std::fflush(stderr);
    const std::string* paths[3] = {&job.stdinPath, &job.stdoutPath, &job.stderrPath};
    for (int fd = 0; fd < 3; ++fd) {
      const std::string& path = paths[fd]->empty() ? devNull_ : *paths[fd];
      int flags = fd == 0 ? O_RDONLY : O_WRONLY | O_CREAT | O_TRUNC;
      int opened = ::open(path.c_str(), flags | O_CLOEXEC | O_NOFOLLOW, 0600);
      if (opened < 0) {
        error = "cannot open " + path + ": " + std::strerror(errno);
        return;
      }
      // Kept from whatever the program may start (spawn = true): rb test's own output and
      // report are not the program's to write.
      saved_[fd] = ::fcntl(fd, F_DUPFD_CLOEXEC, 3);
      ::dup2(opened, fd);
      ::close(opened);
    }
    char cwd[4096];
    if (::getcwd(cwd, sizeof cwd)) cwd_ = cwd;
    if (!job.cwd.empty() && ::chdir(job.cwd.c_str()) != 0) error = "cannot enter " + job.cwd + ": " + std::strerror(errno);
  }
  JobStreams(const JobStreams&) = delete;
  JobStreams& operator=(const JobStreams&) = delete;
  ~JobStreams() {
    std::fflush(stdout);
    std::fflush(stderr);
    for (int fd = 0; fd < 3; ++fd)
      if (saved_[fd] >= 0) {
        ::dup2(saved_[fd], fd);
        ::close(saved_[fd]);
      }
    __fpurge(stdin);
    std::clearerr(stdin);
    if (!cwd_.empty() && ::chdir(cwd_.c_str()) != 0) std::fprintf(stderr, "rb test: cannot go back to %s\n", cwd_.c_str());
  }
  std::string error;

 private:
  const std::string devNull_ = "/dev/null";
  int saved_[3] = {-1, -1, -1};
  std::string cwd_;
};

}  // namespace

void addTestJobCommand(CLI::App& app, int& exitCode, bool withOptions) {
  addJobCommand(app, exitCode, withOptions, false);
}

grade::JobOutcome runJobInProcess(const grade::Job& job) {
  grade::JobOutcome outcome;
  auto start = std::chrono::steady_clock::now();
  // argv: rb itself, the job's subcommand and its options, parsed as `rb test-job` parses them.
  std::vector<std::string> args(job.argv.rbegin(), job.argv.rend() - 1);
  if (std::find(args.begin(), args.end(), "--allow-spawn") != args.end()) {
    // rb's own rules stop a program's own file access at its folder; what it starts, only the
    // kernel's rules confine.
    outcome.error = "rb test --in-process runs no program that may start others (spawn = true): "
                    "only the kernel's confinement holds what they start";
    return outcome;
  }
  int code = 0;
  {
    JobStreams streams(job);
    if (!streams.error.empty()) {
      outcome.error = streams.error;
      return outcome;
    }
    try {
      CLI::App app("rb");
      addJobCommand(app, code, true, true);
      app.parse(args);
      outcome.kind = grade::JobOutcome::Exited;
      outcome.code = code;
    } catch (const CLI::ParseError& e) {
      outcome.error = std::string("rb test-job: ") + e.what();
    } catch (const std::exception& e) {
      outcome.error = std::string("rb failed: ") + e.what();
    }
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace rb::cli
