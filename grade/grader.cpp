#include "grader.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <thread>

#include "pictures.h"

namespace rb::grade {

namespace fs = std::filesystem;

namespace {

/// The largest file a child may write (its output, its record, its screen).
constexpr uint64_t kFileLimit = 64ull << 20;
/// Memory of a run in comment mode (an assignment sets its own).
constexpr uint64_t kCommentMemoryMb = 1024;
/// How much of a program's output and errors a report keeps.
constexpr size_t kReportCap = 64 << 10;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool isNontest(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string first;
  std::getline(in, first);
  CommentSpec spec;
  parseComments(first, file.filename().string(), true, spec);
  return spec.nontest;
}

/// Reads at most `cap` bytes of a file; `cut` tells whether there was more.
std::string readCapped(const std::string& path, size_t cap, bool* cut = nullptr) {
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  uintmax_t size = fs::file_size(path, ec);
  if (ec) size = 0;
  std::string data(std::min<uintmax_t>(size, cap) + 1, '\0');
  in.read(data.data(), static_cast<std::streamsize>(data.size()));
  data.resize(static_cast<size_t>(in.gcount()));
  bool more = data.size() > cap;
  if (more) data.resize(cap);
  if (cut) *cut = more;
  return data;
}

std::string isoNow() {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

bool hasOption(const std::vector<std::string>& args, const std::string& name) {
  for (const std::string& a : args)
    if (a == name || a.rfind(name + "=", 0) == 0) return true;
  return false;
}

/// One run to do: a program (or the solution) with one seed.
struct Task {
  size_t program;    ///< index into the programs (SIZE_MAX: the solution)
  size_t seedIndex;
  uint64_t seed;
  bool screen;       ///< capture the final screen
  Job job;
  std::string record, screenFile;
};

class Grader {
 public:
  explicit Grader(const GradeOptions& o) : opts_(o) {}

  ClassResult run();

 private:
  bool prepare();
  Task makeTask(size_t program, const std::string& file, size_t seedIndex, uint64_t seed,
                bool screen, const CommentSpec* spec);
  RunOutcome collect(const Task& task, const JobOutcome& outcome) const;
  void finishProgram(size_t index);
  void writePicture(ProgramResult& result, const std::vector<RunOutcome>& runs);
  std::string describeProcess(const JobOutcome& o, const Job& job) const;

  const GradeOptions& opts_;
  ClassResult result_;
  std::optional<Assignment> assignment_;
  References refs_;
  std::string temp_;
  size_t taskCount_ = 0;
  std::vector<std::string> programs_;
  std::vector<std::optional<CommentSpec>> specs_;
  std::vector<std::vector<RunOutcome>> runs_;
  std::vector<size_t> pending_;  ///< runs still to come, per program
  size_t finished_ = 0, toGrade_ = 0;
};

std::string Grader::describeProcess(const JobOutcome& o, const Job& job) const {
  std::string text = describe(o, job);
  if (o.kind == JobOutcome::TimedOut && assignment_) {
    // The run had --timeout and did not stop itself by then (one statement ran long): say both.
    char buf[160];
    std::snprintf(buf, sizeof buf, "did not finish: killed after %g s (the time limit is %g s)", job.timeoutSeconds,
                  opts_.timeout.value_or(assignment_->timeout));
    text = buf;
  }
  if (o.kind == JobOutcome::Signalled && job.memoryBytes && !memoryLimitUnsupported() &&
      (o.signal == SIGABRT || o.signal == SIGSEGV || o.signal == SIGBUS))
    text += "; perhaps out of memory (the limit is " + std::to_string(job.memoryBytes >> 20) + " MB)";
  return text;
}

Task Grader::makeTask(size_t program, const std::string& file, size_t seedIndex, uint64_t seed,
                      bool screen, const CommentSpec* spec) {
  Task t;
  t.program = program;
  t.seedIndex = seedIndex;
  t.seed = seed;
  t.screen = screen;
  std::string base = temp_ + "/" + std::to_string(taskCount_++);
  t.record = base + ".json";
  t.screenFile = screen ? base + ".ppm" : "";
  Job& job = t.job;
  job.argv = opts_.childCommand;
  job.argv.insert(job.argv.end(), {"--record", t.record});
  if (screen) job.argv.insert(job.argv.end(), {"--screen", t.screenFile});
  job.stdoutPath = base + ".out";
  job.stderrPath = base + ".err";
  job.fileBytes = kFileLimit;
  fs::path path = fs::absolute(file);
  job.cwd = path.parent_path().string();
  std::vector<std::string> stdinLines;
  if (spec) {
    for (size_t i = 0; i < spec->checkArgs.size(); ++i)
      if (spec->checkArgs[i] == "--target=rb9" ||
          (spec->checkArgs[i] == "--target" && i + 1 < spec->checkArgs.size() && spec->checkArgs[i + 1] == "rb9"))
        job.argv.insert(job.argv.end(), {"--check-target", "rb9"});
    job.argv.insert(job.argv.end(), spec->args.begin(), spec->args.end());
    if (!hasOption(spec->args, "--seed")) job.argv.insert(job.argv.end(), {"--seed", std::to_string(seed)});
    if (opts_.maxSteps && !hasOption(spec->args, "--max-steps"))
      job.argv.insert(job.argv.end(), {"--max-steps", std::to_string(*opts_.maxSteps)});
    // As rb check and rb run each had the time limit, the child that does both gets twice it.
    job.timeoutSeconds = 2 * opts_.timeout.value_or(spec->timeout);
    job.memoryBytes = kCommentMemoryMb << 20;
    stdinLines = spec->stdinLines;
  } else {
    const Assignment& a = *assignment_;
    for (const Check& c : a.checks)
      if (c.kind == Check::Clean && !c.target.empty()) {
        job.argv.insert(job.argv.end(), {"--check-target", c.target});
        break;
      }
    double timeout = opts_.timeout.value_or(a.timeout);
    job.argv.insert(job.argv.end(), {"--seed", std::to_string(seed)});
    job.argv.insert(job.argv.end(), {"--max-steps", std::to_string(opts_.maxSteps.value_or(a.maxSteps))});
    char secs[32];
    std::snprintf(secs, sizeof secs, "%g", timeout);
    job.argv.insert(job.argv.end(), {"--timeout", secs});
    if (!a.events.empty()) job.argv.insert(job.argv.end(), {"--events", a.events});
    if (!a.keys.empty()) job.argv.insert(job.argv.end(), {"--keys", a.keys});
    // The interpreter stops itself at the timeout and says where; the kill is the backstop for
    // a single statement that never returns.
    job.timeoutSeconds = timeout * 1.5 + 1;
    job.memoryBytes = a.memoryMb << 20;
    stdinLines = a.stdinLines;
  }
  if (!stdinLines.empty()) {
    job.stdinPath = base + ".in";
    std::ofstream in(job.stdinPath, std::ios::binary);
    for (const std::string& line : stdinLines) in << line << '\n';
  }
  job.argv.insert(job.argv.end(), {"--", path.filename().string()});
  return t;
}

RunOutcome Grader::collect(const Task& t, const JobOutcome& outcome) const {
  RunOutcome run;
  run.seed = t.seed;
  run.process = outcome;
  run.processText = describeProcess(outcome, t.job);
  run.output = readCapped(t.job.stdoutPath, kOutputCap, &run.outputCut);
  run.errors = readCapped(t.job.stderrPath, kOutputCap);
  std::error_code ec;
  if (outcome.kind == JobOutcome::Exited && fs::exists(t.record, ec)) {
    std::string text = readCapped(t.record, kFileLimit);
    run.record = recordFromJson(text, run.recordError);
  } else {
    run.recordError = "no record";
  }
  if (run.record && run.record->screen && t.screen) {
    std::string error;
    run.screen = readScreenFile(t.screenFile, error);
  }
  for (const std::string& f : {t.record, t.screenFile, t.job.stdoutPath, t.job.stderrPath, t.job.stdinPath})
    if (!f.empty()) fs::remove(f, ec);
  return run;
}

bool Grader::prepare() {
  if (!opts_.assignmentPath.empty()) {
    std::string error;
    assignment_ = loadAssignment(opts_.assignmentPath, error);
    if (!assignment_) {
      result_.fatal = error;
      result_.fatalCode = 64;
      return false;
    }
    result_.title = assignment_->title;
    for (const Check& c : assignment_->checks) {
      std::optional<render::RgbImage> picture;
      if (c.kind == Check::Screen) {
        std::string error2;
        picture = render::readPngFile(c.picture, error2);
        if (!picture) {
          result_.fatal = opts_.assignmentPath + ": " + error2;
          result_.fatalCode = 66;
          return false;
        }
      }
      refs_.pictures.push_back(std::move(picture));
    }
  }
  std::vector<std::string> found;
  try {
    found = findPrograms(opts_.paths);
  } catch (const std::runtime_error& e) {
    result_.fatal = e.what();
    result_.fatalCode = 66;
    return false;
  }
  if (assignment_ && assignment_->solution) {
    std::error_code ec;
    fs::path sol = fs::weakly_canonical(*assignment_->solution, ec);
    found.erase(std::remove_if(found.begin(), found.end(),
                               [&](const std::string& p) { return fs::weakly_canonical(p, ec) == sol; }),
                found.end());
  }
  if (found.empty()) {
    result_.fatal = "no programs to grade (no .bas files)";
    result_.fatalCode = 66;
    return false;
  }
  programs_ = shardOf(found, opts_.shard, opts_.shards);

  std::string pattern = (fs::temp_directory_path() / "rb-test-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    result_.fatal = "cannot make a temporary folder: " + std::string(std::strerror(errno));
    result_.fatalCode = 74;
    return false;
  }
  temp_ = pattern;
  if (!opts_.picturesDir.empty()) {
    std::error_code ec;
    fs::create_directories(opts_.picturesDir, ec);
    if (ec) {
      result_.fatal = "cannot make the pictures folder " + opts_.picturesDir + ": " + ec.message();
      result_.fatalCode = 74;
      return false;
    }
  }
  return true;
}

ClassResult Grader::run() {
  auto start = std::chrono::steady_clock::now();
  result_.title = "rb test";
  result_.timestamp = isoNow();
  if (!prepare()) return result_;
  int parallel = opts_.jobs > 0 ? opts_.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  // The solution first: every program is compared with it.
  bool pictures = !opts_.picturesDir.empty();
  if (assignment_ && assignment_->solution && (assignment_->needsSolution() || pictures)) {
    std::vector<Task> tasks;
    std::vector<Job> jobs;
    for (size_t s = 0; s < assignment_->seeds.size(); ++s) {
      tasks.push_back(makeTask(SIZE_MAX, *assignment_->solution, s, assignment_->seeds[s],
                               assignment_->needsScreen() || pictures, nullptr));
      jobs.push_back(tasks.back().job);
    }
    refs_.solution.resize(tasks.size());
    runJobs(jobs, parallel, [&](size_t i, const JobOutcome& o) { refs_.solution[i] = collect(tasks[i], o); });
    for (const RunOutcome& s : refs_.solution) {
      std::string why = unrunnable(s);
      if (why.empty() && s.record) why = stopDescription(*s.record);
      if (!why.empty()) {
        result_.fatal = "the solution " + *assignment_->solution + " does not run cleanly" +
                        (refs_.solution.size() > 1 ? " with seed " + std::to_string(s.seed) : "") + ": " + why;
        result_.fatalCode = 1;
        fs::remove_all(temp_);
        return result_;
      }
    }
  }

  // The class.
  result_.programs.resize(programs_.size());
  specs_.resize(programs_.size());
  runs_.resize(programs_.size());
  pending_.assign(programs_.size(), 0);
  std::vector<Task> tasks;
  for (size_t p = 0; p < programs_.size(); ++p) {
    ProgramResult& r = result_.programs[p];
    r.program = programs_[p];
    if (!assignment_) {
      specs_[p] = readCommentSpec(programs_[p]);
      if (!specs_[p]) {
        r.verdict = "error";
        r.reason = "cannot read " + programs_[p];
        continue;
      }
      if (specs_[p]->nontest || specs_[p]->skip) {
        r.verdict = "skip";
        r.reason = specs_[p]->nontest ? "not a test (// nontest: a file others include)" : *specs_[p]->skip;
        continue;
      }
      tasks.push_back(makeTask(p, programs_[p], 0, opts_.seed, false, &*specs_[p]));
      pending_[p] = 1;
    } else {
      for (size_t s = 0; s < assignment_->seeds.size(); ++s)
        tasks.push_back(makeTask(p, programs_[p], s, assignment_->seeds[s], assignment_->needsScreen(), nullptr));
      pending_[p] = assignment_->seeds.size();
    }
    runs_[p].resize(pending_[p]);
    ++toGrade_;
  }
  std::vector<Job> jobs;
  for (const Task& t : tasks) jobs.push_back(t.job);
  runJobs(jobs, parallel, [&](size_t i, const JobOutcome& o) {
    const Task& t = tasks[i];
    runs_[t.program][t.seedIndex] = collect(t, o);
    if (--pending_[t.program] == 0) finishProgram(t.program);
  });
  std::error_code ec;
  fs::remove_all(temp_, ec);

  for (const ProgramResult& r : result_.programs) {
    if (r.verdict == "pass") ++result_.passed;
    else if (r.verdict == "skip") ++result_.skipped;
    else if (r.verdict == "error") ++result_.errors;
    else ++result_.failed;
  }
  result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result_;
}

void Grader::finishProgram(size_t index) {
  ProgramResult& r = result_.programs[index];
  std::vector<RunOutcome>& runs = runs_[index];
  r.checks = assignment_ ? checkAssignment(*assignment_, refs_, runs) : checkComments(*specs_[index], runs[0]);
  r.verdict = "pass";
  for (const CheckResult& c : r.checks) {
    r.maxPoints += c.points;
    if (c.passed) {
      r.points += c.points;
    } else if (r.verdict == "pass") {
      r.verdict = "fail";
      r.reason = c.message;
    }
  }
  for (const RunOutcome& run : runs) {
    r.seconds += run.process.seconds;
    // rb itself failed (not a limit the program ran into): the program could not be graded.
    if (run.process.kind == JobOutcome::NotStarted ||
        (run.process.kind == JobOutcome::Signalled && run.process.signal != SIGXCPU &&
         run.process.signal != SIGXFSZ && run.process.signal != SIGKILL))
      r.verdict = "error";
  }
  const RunOutcome& first = runs[0];
  if (first.record) r.steps = first.record->steps;
  r.output = first.output.substr(0, kReportCap);
  r.errors = first.errors.substr(0, kReportCap);
  if (!opts_.picturesDir.empty()) writePicture(r, runs);
  for (RunOutcome& run : runs) run.screen.reset();  // a class's screens would not fit in memory
  ++finished_;
  if (opts_.progress) opts_.progress(finished_, toGrade_);
}

void Grader::writePicture(ProgramResult& r, const std::vector<RunOutcome>& runs) {
  const RunOutcome& run = runs[0];
  if (!run.record) return;
  PictureInput in;
  in.student = run.record->trail;
  if (run.record->located) in.studentEnd = run.record->pos;
  if (!refs_.solution.empty() && refs_.solution[0].record) {
    const RunRecord& sol = *refs_.solution[0].record;
    in.reference = sol.trail;
    if (sol.located) in.referenceEnd = sol.pos;
    in.background = refs_.solution[0].screen;
  } else if (assignment_) {
    for (const Check& c : assignment_->checks)
      if (c.kind == Check::Trail) {
        in.reference = c.reference;
        break;
      }
  }
  std::string name = r.program;
  while (name.rfind("./", 0) == 0 || name.rfind("../", 0) == 0) name = name.substr(name.find('/') + 1);
  while (!name.empty() && name[0] == '/') name.erase(0, 1);
  std::replace(name.begin(), name.end(), '/', '_');
  fs::path out = fs::path(opts_.picturesDir) / fs::path(name).replace_extension(".png");
  std::string error;
  if (render::writePngFile(out.string(), feedbackPicture(in), error)) r.picture = out.string();
}

}  // namespace

std::vector<std::string> findPrograms(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  auto add = [&](const fs::path& p) {
    std::error_code ec;
    std::string key = fs::weakly_canonical(p, ec).string();
    if (seen.insert(key).second) out.push_back(p.lexically_normal().string());
  };
  for (const std::string& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<fs::path> files;
      for (fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
           !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && lower(it->path().extension().string()) == ".bas" && !isNontest(it->path()))
          files.push_back(it->path());
      }
      std::sort(files.begin(), files.end());
      for (const fs::path& f : files) add(f);
    } else if (fs::exists(path, ec)) {
      add(path);
    } else {
      throw std::runtime_error(path + ": no such file or folder");
    }
  }
  return out;
}

std::vector<std::string> shardOf(const std::vector<std::string>& programs, int shard, int shards) {
  if (shards <= 1) return programs;
  std::vector<std::string> out;
  for (size_t i = 0; i < programs.size(); ++i)
    if (static_cast<int>(i % static_cast<size_t>(shards)) == shard - 1) out.push_back(programs[i]);
  return out;
}

ClassResult gradeClass(const GradeOptions& options) { return Grader(options).run(); }

}  // namespace rb::grade
