#include "test_command.h"

#include <CLI/CLI.hpp>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <string>

#include "exit_codes.h"
#include "files.h"
#include "kernel_confine.h"
#include "merge.h"
#include "program_loader.h"
#include "grader.h"
#include "html_report.h"
#include "png_writer.h"
#include "report.h"
#include "similarity.h"
#include "run_command.h"
#include "test_job.h"
#include "text.h"

namespace rb::cli {

namespace {

struct TestOptions {
  std::vector<std::string> paths;
  std::string assignment;
  int jobs = 0;
  std::string shard;
  uint64_t seed = 1;
  std::optional<uint64_t> maxSteps;
  std::optional<double> timeout;
  std::string format = "text";
  std::string junit, csv, pictures, feedback, replays, html;
  std::vector<std::string> include;
  std::string roster;
  bool student = false;
  bool trustComments = false;
  bool similarity = false;
  std::vector<std::string> similarityIgnore;
  bool quiet = false;
  bool requireSandbox = false;
  bool inProcess = false;
  std::vector<std::string> merge, mergePictures;
};

/// A teacher's program (world, post) as rb check sees it: its first error, or "".
std::string firstError(const std::string& file) {
  run::LoadedFile loaded = run::loadFile(file, CompileOptions{}, false);
  if (loaded.exitCode == run::exitcode::kNoInput) return file + ": cannot read it: " + loaded.readError;
  if (loaded.compiled) return "";
  for (const Diagnostic& d : loaded.diags.all()) {
    if (d.severity != Severity::Error) continue;
    const SourceSet& sources = loaded.program->sources;
    std::string name = d.loc.valid() && d.loc.file < sources.size() ? sources.file(d.loc.file).name() : file;
    return name + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": " + d.message;
  }
  return file + ": does not compile";
}

/// The files a program #includes from its own folder tree, as rb run would load them: rb test
/// copies them beside the program into its scratch folder.
std::vector<std::string> includedFiles(const std::string& file) {
  std::optional<std::string> text = run::readFile(file);
  if (!text) return {};
  // Most programs include nothing: no need to load them here.
  std::string lowered = *text;
  for (char& c : lowered) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lowered.find("#include") == std::string::npos) return {};
  run::LoadedFile loaded = run::loadFile(file, CompileOptions{}, false, true);
  std::vector<std::string> out;
  if (!loaded.program) return out;
  for (uint32_t i = 1; i < loaded.program->sources.size(); ++i) out.push_back(loaded.program->sources.file(i).name());
  return out;
}

/// "rb test: MESSAGE" on standard error. A message may quote a student's file name: it is shown
/// as the reports show untrusted text (text.h), on one line, whole even with a NUL in it.
void say(const std::string& message) {
  std::string text = "rb test: " + record::shownText(message, record::TextShape::Line) + "\n";
  std::fwrite(text.data(), 1, text.size(), stderr);
}

/// One feedback file per program for its student: DIR/NAME.txt.
bool writeFeedback(const std::string& dir, const grade::ClassResult& result, const std::vector<std::string>& paths) {
  std::string why;
  if (!render::makeFolder(dir, why)) {
    say(why);
    return false;
  }
  bool ok = true;
  for (const grade::ProgramResult& p : result.programs) {
    std::string text = grade::studentFeedback(p, result), error;
    std::string name = p.name.empty() ? grade::reportName(p.program, paths) : p.name;
    std::string path = (std::filesystem::path(dir) / (name + ".txt")).string();
    if (!render::writeFileBytes(path, text.data(), text.size(), error)) {
      say(error);
      ok = false;
    }
  }
  return ok;
}

/// "K/N" with 1 <= K <= N; false when it is not that.
bool parseShard(const std::string& text, int& k, int& n) {
  size_t slash = text.find('/');
  if (slash == std::string::npos) return false;
  try {
    size_t used1 = 0, used2 = 0;
    k = std::stoi(text.substr(0, slash), &used1);
    n = std::stoi(text.substr(slash + 1), &used2);
    return used1 == slash && used2 == text.size() - slash - 1 && n >= 1 && k >= 1 && k <= n;
  } catch (const std::exception&) {
    return false;
  }
}

bool writeReport(const std::string& path, const std::string& text) {
  std::string error;
  if (render::writeFileBytes(path, text.data(), text.size(), error)) return true;
  say(error);
  return false;
}

/// Every report asked for of a graded (or merged) class; rb test's exit status.
int writeClassReports(const TestOptions& opts, const grade::ClassResult& result) {
  const std::vector<std::string>& paths = result.origin.paths;
  for (const std::string& w : result.warnings) say("warning: " + w);
  for (const std::string& e : result.writeErrors) say(e);
  bool written = result.writeErrors.empty();
  if (!opts.feedback.empty()) written = writeFeedback(opts.feedback, result, paths) && written;
  if (!opts.junit.empty()) written = writeReport(opts.junit, grade::junitReport(result)) && written;
  if (!opts.csv.empty()) written = writeReport(opts.csv, grade::csvReport(result)) && written;
  if (!opts.html.empty()) {
    std::string error;
    if (!grade::writeHtmlReport(result, paths, opts.html, error)) {
      say(error);
      written = false;
    }
  }
  std::string out = opts.format == "json" ? grade::jsonReport(result) : grade::textReport(result, !opts.quiet);
  if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size() || std::fflush(stdout) != 0) {
    std::fprintf(stderr, "rb test: cannot write to standard output\n");
    return run::exitcode::kIoError;
  }
  if (!written) return run::exitcode::kIoError;
  return result.failed + result.errors + result.missing == 0 ? run::exitcode::kOk : 1;
}

int executeTest(const TestOptions& opts) {
  grade::GradeOptions g;
  g.paths = opts.paths.empty() ? std::vector<std::string>{"."} : opts.paths;
  g.assignmentPath = opts.assignment;
  g.jobs = opts.jobs;
  if (!opts.shard.empty() && !parseShard(opts.shard, g.shard, g.shards)) {
    std::fprintf(stderr, "rb test: --shard wants K/N with 1 <= K <= N (like 2/4), not '%s'\n", opts.shard.c_str());
    return run::exitcode::kUsage;
  }
  g.seed = opts.seed;
  g.maxSteps = opts.maxSteps;
  g.timeout = opts.timeout;
  g.picturesDir = opts.pictures;
  g.studentPictures = opts.student;
  g.replayFormat = opts.replays;
  if (!opts.html.empty()) {
    // The class report page shows each program's final screen, its picture and its replay:
    // written beside the page (DIR/pictures) unless --pictures puts them elsewhere.
    if (g.picturesDir.empty()) g.picturesDir = (std::filesystem::path(opts.html) / "pictures").string();
    if (g.replayFormat.empty()) g.replayFormat = "html";
    g.screens = true;
  }
  if (!opts.replays.empty() && g.picturesDir.empty()) {
    std::fprintf(stderr, "rb test: --replays writes beside the pictures: give --pictures DIR too\n");
    return run::exitcode::kUsage;
  }
  g.include = opts.include;
  g.roster = opts.roster;
  g.trustComments = opts.trustComments;
  g.compileProgram = firstError;
  g.includedFiles = includedFiles;
  g.requireSandbox = opts.requireSandbox;
  if (opts.inProcess) {
    if (opts.requireSandbox) {
      std::fprintf(stderr, "rb test: --in-process runs the programs without the kernel's confinement: leave out --require-sandbox\n");
      return run::exitcode::kUsage;
    }
    g.runJob = runJobInProcess;
  }
  if (opts.requireSandbox) {
    if (std::string gap = run::kernelConfinementGap(); !gap.empty()) {
      std::fprintf(stderr, "rb test: --require-sandbox: %s\n", gap.c_str());
      return run::exitcode::kUnavailable;
    }
  }
  g.similarity = opts.similarity || !opts.similarityIgnore.empty();
  g.similarityIgnore = opts.similarityIgnore;
  if ((!opts.include.empty() || !opts.roster.empty()) && opts.assignment.empty()) {
    std::fprintf(stderr, "rb test: --include and --roster grade a class folder against an assignment (-a FILE)\n");
    return run::exitcode::kUsage;
  }
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) {
    std::fprintf(stderr, "rb test: cannot find rb's own executable: %s\n", ec.message().c_str());
    return run::exitcode::kIoError;
  }
  g.childCommand = {self.string(), kTestJobCommand};
  if (!opts.quiet && isatty(2)) {
    g.progress = [](size_t done, size_t total) {
      std::fprintf(stderr, "\rrb test: %zu of %zu graded", done, total);
      if (done == total) std::fprintf(stderr, "\r\033[K");
      std::fflush(stderr);
    };
  }

  if (!opts.html.empty()) {
    std::string why;
    if (!render::makeFolder(opts.html, why)) {
      std::fprintf(stderr, "rb test: %s\n", why.c_str());
      return run::exitcode::kIoError;
    }
  }
  grade::ClassResult result = grade::gradeClass(g);
  if (result.interruptedBy) {
    // Ctrl-C (or kill): the programs were ended and the temporary files removed; no report, and
    // rb ends by the same signal, as the shell expects.
    std::fflush(stdout);
    std::signal(result.interruptedBy, SIG_DFL);
    std::raise(result.interruptedBy);
    return 128 + result.interruptedBy;
  }
  if (result.fatalCode) {
    say(result.fatal);
    return result.fatalCode;
  }
  result.studentView = opts.student;
  if (opts.student)
    for (grade::ProgramResult& p : result.programs) p = grade::forStudents(std::move(p));
  // What tells this grading from another, for rb test --merge (the JSON report carries it).
  result.origin.paths = g.paths;
  result.origin.shard = g.shard;
  result.origin.shards = g.shards;
  result.origin.rbVersion = RB_VERSION;
  if (!opts.assignment.empty()) {
    result.origin.assignmentFile = opts.assignment;
    if (std::optional<std::string> bytes = run::readFile(opts.assignment)) result.origin.assignmentDigest = grade::contentDigest(*bytes);
  }
  // The name each report gives a program, in the JSON too (a missing student's from the roster).
  for (grade::ProgramResult& p : result.programs)
    if (p.name.empty()) p.name = grade::reportName(p.program, g.paths);
  return writeClassReports(opts, result);
}

/// rb test --merge: the shards' JSON reports read back and merged, then every report written as
/// one run over the whole class writes it. `grading`: options given that only grading takes.
int executeMerge(const TestOptions& opts, const std::vector<std::string>& grading) {
  if (!grading.empty()) {
    std::string list;
    for (const std::string& o : grading) list += (list.empty() ? "" : ", ") + o;
    say("--merge reads the shards' reports and grades nothing: leave out " + list);
    return run::exitcode::kUsage;
  }
  if (!opts.mergePictures.empty() && opts.mergePictures.size() != opts.merge.size()) {
    say("--merge-pictures names one folder per report, in the reports' order: " + std::to_string(opts.merge.size()) +
        " reports, " + std::to_string(opts.mergePictures.size()) + " folders");
    return run::exitcode::kUsage;
  }
  std::vector<grade::ShardReport> shards;
  std::vector<grade::MissingPicture> missing;
  bool shardSimilarity = false;
  for (size_t i = 0; i < opts.merge.size(); ++i) {
    int code = 0;
    std::string error;
    std::optional<grade::ShardReport> shard = grade::loadShard(opts.merge[i], code, error);
    if (!shard) {
      say(error);
      return code;
    }
    grade::findShardPictures(*shard, opts.mergePictures.empty() ? "" : opts.mergePictures[i], missing);
    shardSimilarity = shardSimilarity || shard->similarity;
    shards.push_back(std::move(*shard));
  }
  grade::MergeOutcome merged = grade::mergeShards(std::move(shards));
  if (merged.code) {
    say(merged.error);
    return merged.code;
  }
  grade::ClassResult& result = merged.result;
  // The pictures go where one run would write them: --pictures DIR, else beside the page.
  std::string pictures = !opts.pictures.empty() ? opts.pictures
                         : !opts.html.empty()   ? (std::filesystem::path(opts.html) / "pictures").string()
                                                : "";
  if (!missing.empty()) {
    std::string what = std::to_string(missing.size()) + " picture" + (missing.size() == 1 ? "" : "s") +
                       " (screens, replays) the reports name " + (missing.size() == 1 ? "is" : "are") +
                       " not found (the first: '" + missing[0].recorded + "' of " + missing[0].report + ")";
    if (!pictures.empty()) {
      say(what + ": give each report's pictures folder with --merge-pictures DIR...");
      return run::exitcode::kNoInput;
    }
    say("note: " + what + ": the merged reports name none of them");
  }
  if (shardSimilarity && !opts.similarity && opts.similarityIgnore.empty())
    say("note: the shards' similarity lists compare each shard's own programs only and are left out: give "
        "--similarity to compare the whole class");
  std::string why;
  if (!opts.html.empty() && !render::makeFolder(opts.html, why)) {
    say(why);
    return run::exitcode::kIoError;
  }
  if (!pictures.empty()) {
    if (!render::makeFolder(pictures, why)) {
      say(why);
      return run::exitcode::kIoError;
    }
    grade::copyPictures(result, pictures, result.writeErrors);
  }
  if (opts.similarity || !opts.similarityIgnore.empty())
    result.similarity = grade::classSimilarity(result, opts.similarityIgnore);
  return writeClassReports(opts, result);
}

}  // namespace

void addTestCommand(CLI::App& app, int& exitCode, bool withOptions) {
  auto opts = std::make_shared<TestOptions>();
  CLI::App* test = app.add_subcommand(
      "test", "Grade programs against the expectations in their comments or an assignment file");
  if (!withOptions) return;
  test->add_option("paths", opts->paths, "Programs and folders (searched for *.bas); default: .");
  test->add_option("-a,--assignment", opts->assignment,
                   "Grade against this assignment file (TOML; see man rb-test) instead of the "
                   "programs' comments")
      ->type_name("FILE");
  test->add_option("-j,--jobs", opts->jobs, "Programs to run at once (default: one per core)")
      ->type_name("N")
      ->check(kJobs);
  test->add_option("--shard", opts->shard,
                   "Grade only every N-th program starting with the K-th (of the sorted list), to "
                   "spread a class over N CI jobs")
      ->type_name("K/N");
  test->add_option("--merge", opts->merge,
                   "Grade nothing: merge the JSON reports of a class's shards (rb test --shard K/N "
                   "--format json, every shard once) and write the class's reports, as one run over the "
                   "whole class writes them")
      ->type_name("REPORT.json...");
  test->add_option("--merge-pictures", opts->mergePictures,
                   "With --merge: each report's pictures folder, in the reports' order (default: the "
                   "paths the reports recorded, or beside each report)")
      ->type_name("DIR...");
  test->add_option("--seed", opts->seed,
                   "Seed of runs whose comments give none (default 1; an assignment lists its own)")
      ->type_name("N");
  test->add_option("--max-steps", opts->maxSteps,
                   "Stop each run after N statements (overrides the assignment; 0: no limit)")
      ->type_name("N")
      ->check(kStepCount);
  test->add_option("--timeout", opts->timeout,
                   "Seconds each run may take (overrides the assignment and // timeout:)")
      ->type_name("SECONDS")
      ->check(kLimitSeconds);
  test->add_option("--format", opts->format, "Summary on standard output: text (a table) or json")
      ->check(CLI::IsMember({"text", "json"}));
  test->add_option("--junit", opts->junit, "Also write a JUnit XML report to FILE")->type_name("FILE");
  test->add_option("--csv", opts->csv, "Also write a CSV grade book to FILE")->type_name("FILE");
  test->add_option("--pictures", opts->pictures,
                   "Write one PNG per program into DIR: its robot's path and trail (red) over the solution's "
                   "(green), the waypoints, regions and colours asked for, where checks failed, a legend "
                   "(with --student: no solution)")
      ->type_name("DIR");
  test->add_option("--replays", opts->replays,
                   "With --pictures (or --html): also a replay of each program's run beside its "
                   "picture, as an animated gif, an animated svg or an html player")
      ->type_name("FORMAT")
      ->check(CLI::IsMember({"gif", "svg", "html"}));
  test->add_option("--html", opts->html,
                   "Write the class report page into DIR: index.html with a card per program (points, "
                   "final screen, checks; sortable and filterable) and a page per program (source with "
                   "the failing lines marked, feedback, picture, replay). Static, no network; pictures "
                   "and replays go to DIR/pictures unless --pictures says otherwise")
      ->type_name("DIR");
  test->add_option("--feedback", opts->feedback,
                   "Write one text file per program into DIR for its student: every check with its "
                   "points and hints, hidden checks only as 'a hidden check failed'")
      ->type_name("DIR");
  test->add_flag("--student", opts->student,
                 "Reports and pictures for students: hidden checks say only that they failed; "
                 "pictures never show the solution's drawing");
  test->add_option("--include", opts->include,
                   "Also grade files whose name matches GLOB as programs (like '*.bas.txt'); "
                   "repeatable; other files of the class folder are listed as not graded")
      ->type_name("GLOB");
  test->add_option("--roster", opts->roster,
                   "A CSV of students (student,file or folder): names in every report, students "
                   "with no submission listed as missing (overrides the assignment's roster)")
      ->type_name("FILE");
  test->add_flag("--trust-comments", opts->trustComments,
                 "Let // args: grant what only the person running rb may (--allow-files, "
                 "--allow-spawn, --port, --real) and // timeout: go past 30 s");
  test->add_flag("--similarity", opts->similarity,
                 "Also list pairs of programs whose code is much alike (names, numbers, comments and "
                 "layout ignored), with the matching lines side by side: an aid, never a verdict");
  test->add_option("--similarity-ignore", opts->similarityIgnore,
                   "Code of FILE (a template students started from) does not count as shared; "
                   "repeatable; implies --similarity")
      ->type_name("FILE")
      ->check(CLI::ExistingFile);
  test->add_flag("-q,--quiet", opts->quiet, "Only the table: no details of failed checks, no progress");
  test->add_flag("--require-sandbox", opts->requireSandbox,
                 "Refuse to grade when the kernel cannot confine the programs (no Landlock or seccomp), "
                 "instead of saying so in every report");
  test->add_flag("--in-process", opts->inProcess,
                 "Run each program inside rb itself, one at a time, as the web page grades: rb's own "
                 "rules confine it (its folder, no other programs), not the kernel's");
  test->footer(
      "Each program runs in a child process of its own (rb itself), with a time and memory "
      "limit, so a crash or a hang fails that program alone. Exit status: 0 every program "
      "passed, 1 some failed, 64 bad usage or assignment file, 66 a path does not exist or no "
      "programs (with --merge: a report or a shard is missing), 74 a report cannot be written. "
      "Manual: man rb-test.");
  test->callback([opts, test, &exitCode] {
    if (opts->merge.empty()) {
      if (!opts->mergePictures.empty()) {
        say("--merge-pictures goes with --merge REPORT.json...");
        exitCode = run::exitcode::kUsage;
        return;
      }
      exitCode = executeTest(*opts);
      return;
    }
    // What only grading takes: refused with --merge, which grades nothing.
    std::vector<std::string> grading;
    if (!opts->paths.empty()) grading.push_back("the paths to grade (" + opts->paths.front() + ")");
    for (const char* name : {"--assignment", "--jobs", "--shard", "--seed", "--max-steps", "--timeout", "--replays",
                             "--include", "--roster", "--trust-comments", "--require-sandbox", "--in-process", "--student"})
      if (test->count(name)) grading.push_back(name);
    exitCode = executeMerge(*opts, grading);
  });
}

void addTestSimilarityCommand(CLI::App& app, int& exitCode, bool withOptions) {
  struct Options {
    std::vector<std::string> paths, ignore;
    std::string format = "text";
    size_t threads = 0;
  };
  auto opts = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(kTestSimilarityCommand,
                                     "Compare programs as rb test --similarity does, without grading them (internal)");
  cmd->group("");  // hidden from rb --help: for bench/grade/similarity.sh
  if (!withOptions) return;
  cmd->add_option("paths", opts->paths, "Programs and folders of programs")->required();
  cmd->add_option("--similarity-ignore", opts->ignore, "As rb test's")->check(CLI::ExistingFile);
  cmd->add_option("--format", opts->format, "text or json")->check(CLI::IsMember({"text", "json"}));
  cmd->add_option("--threads", opts->threads, "Threads (default: one for each processor)");
  cmd->callback([opts, &exitCode] {
    for (const std::string& p : opts->paths)
      if (!std::filesystem::exists(p)) {
        say("no such file or folder: '" + p + "'");
        exitCode = run::exitcode::kNoInput;
        return;
      }
    grade::SimilarityOptions options;
    options.ignore = opts->ignore;
    options.threads = opts->threads;
    const grade::SimilarityReport report = grade::findSimilar(grade::findPrograms(opts->paths), options);
    const std::string out = opts->format == "json" ? grade::similarityJson(report) : grade::similarityText(report);
    std::fwrite(out.data(), 1, out.size(), stdout);
    exitCode = run::exitcode::kOk;
  });
}

}  // namespace rb::cli
