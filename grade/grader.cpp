#include "grader.h"

#include <fnmatch.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <thread>

#include "pictures.h"

namespace rb::grade {

using record::DiagRecord;
using record::Region;
using record::RunRecord;
using record::Screen;
using record::imageOf;
using record::readScreenFile;
using record::recordFromJson;
using record::screenOf;

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

/// The largest program rb test grades (as rb run reads at most).
constexpr size_t kMaxProgramBytes = 16u << 20;

/// Reads a program's whole text for grading; false with `why` when it cannot.
bool readSnapshot(const std::string& path, std::string& text, std::string& why) {
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (!fs::is_regular_file(st)) {
    why = fs::exists(st) ? "not a regular file" : "no such file";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = "permission denied";
    return false;
  }
  bool cut = false;
  text = readCapped(path, kMaxProgramBytes, &cut);
  if (cut) {
    why = "larger than " + std::to_string(kMaxProgramBytes >> 20) + " MiB, not a program";
    return false;
  }
  return true;
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
  std::string record, screenFile, replayFile;
  /// The run's own folder in rb test's temporary folder: the files rb test and the job exchange,
  /// and `box`, the scratch folder the program runs in ("" : it runs where it is).
  std::string dir, box;
  std::string mainRel;        ///< the program's copy, relative to box
  std::string studentFolder;  ///< the student's folder copied whole into box, or ""
  /// More files copied into box: what the program #includes, the assignment's files (absolute
  /// source, path in box).
  std::vector<std::pair<std::string, std::string>> copies;
  std::vector<std::string> stdinLines;
};

/// How much one scratch folder may hold: a student's folder bigger than this is not copied for
/// every run, and the program is not graded (the reason says why).
constexpr uintmax_t kScratchBytes = 64ull << 20;
constexpr size_t kScratchEntries = 4096;

struct CopyBudget {
  uintmax_t bytes = 0;
  size_t entries = 0;
  bool over() const { return bytes > kScratchBytes || entries > kScratchEntries; }
};

/// Copies a regular file, made private to the run (0600).
bool copyOne(const fs::path& from, const fs::path& to, CopyBudget& budget, std::string& error) {
  std::error_code ec;
  uintmax_t size = fs::file_size(from, ec);
  if (ec) {
    error = "cannot copy " + from.string() + ": " + ec.message();
    return false;
  }
  budget.bytes += size;
  ++budget.entries;
  if (budget.over()) return true;  // the caller says why
  fs::create_directories(to.parent_path(), ec);
  if (!fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec)) {
    error = "cannot copy " + from.string() + ": " + ec.message();
    return false;
  }
  fs::permissions(to, fs::perms::owner_read | fs::perms::owner_write, ec);
  return true;
}

/// Copies a folder's regular files and folders (not hidden ones, not links, FIFOs or devices).
bool copyTree(const fs::path& from, const fs::path& to, const fs::path& skip, CopyBudget& budget, std::string& error) {
  std::error_code ec;
  fs::create_directories(to, ec);
  for (fs::recursive_directory_iterator it(from, fs::directory_options::skip_permission_denied, ec), end;
       !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    fs::file_status st = it->symlink_status(ec);
    if (!name.empty() && name[0] == '.') {
      if (fs::is_directory(st)) it.disable_recursion_pending();
      continue;
    }
    fs::path dest = to / it->path().lexically_relative(from);
    if (fs::is_directory(st)) {
      fs::create_directories(dest, ec);
      if (++budget.entries > kScratchEntries) return true;
    } else if (fs::is_regular_file(st) && it->path() != skip) {
      if (!copyOne(it->path(), dest, budget, error)) return false;
      if (budget.over()) return true;
    }
  }
  return true;
}

/// The environment of a job: nothing of the grader's own (tokens, keys) reaches a program or
/// what it starts; only what rb and a started program need.
std::vector<std::string> jobEnvironment(const std::string& home) {
  std::vector<std::string> env = {"PATH=/usr/local/bin:/usr/bin:/bin", "HOME=" + home, "TMPDIR=" + home};
  for (const char* name : {"LANG", "LC_ALL", "LC_CTYPE", "TZ", "RB_LIB_PATH", "ASAN_OPTIONS", "UBSAN_OPTIONS",
                           "LSAN_OPTIONS"})
    if (const char* v = std::getenv(name)) env.push_back(std::string(name) + "=" + v);
  return env;
}

/// A comment's timeout above this is capped unless the person running rb test allows more.
constexpr double kCommentTimeoutCap = 30;
/// Memory of a run in comment mode (an assignment sets its own), which `// args:` may lower.
constexpr double kCommentMemoryCapMb = 1024;

/// What `// args:` may pass to the run: what only narrows what the program may do, or reads
/// only from its own folder. The rest is left out, each with why (docs/confinement.md).
struct FilteredArgs {
  std::vector<std::string> args;
  std::vector<std::string> notes;
};

std::optional<double> numberArg(const std::string& s) {
  try {
    size_t used = 0;
    double v = std::stod(s, &used);
    if (used == s.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// The lines of `program` where its run went wrong (ProgramResult::marks): diagnostics and
/// errors in other files (includes) are left out.
std::vector<ProgramResult::LineMark> lineMarks(const RunRecord& record, const std::string& program) {
  std::vector<ProgramResult::LineMark> out;
  std::string name = fs::path(program).filename().string();
  auto add = [&](const DiagRecord& d, const std::string& prefix) {
    if (d.line == 0 || (!d.file.empty() && fs::path(d.file).filename().string() != name)) return;
    for (const ProgramResult::LineMark& m : out)
      if (m.line == d.line && m.message == prefix + d.message) return;
    out.push_back({d.line, prefix + d.message});
  };
  for (const DiagRecord& d : record.checkDiags)
    if (d.severity == "error") add(d, "");
  for (const DiagRecord& d : record.loadErrors) add(d, "");
  if (record.error) add(*record.error, record.status == "limit" ? "stopped here: " : "");
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
  return out;
}

/// The image at half its width and height, each pixel the mean of the four it stands for: the
/// final screens of a class report, a quarter of the pixels to encode and to load.
render::RgbImage halfSize(const render::RgbImage& in) {
  render::RgbImage out;
  out.width = in.width / 2;
  out.height = in.height / 2;
  out.rgb.resize(static_cast<size_t>(out.width) * static_cast<size_t>(out.height) * 3);
  size_t stride = static_cast<size_t>(in.width) * 3;
  uint8_t* o = out.rgb.data();
  for (int y = 0; y < out.height; ++y) {
    const uint8_t* a = in.rgb.data() + static_cast<size_t>(2 * y) * stride;
    const uint8_t* b = a + stride;
    for (int x = 0; x < out.width; ++x, a += 6, b += 6)
      for (int c = 0; c < 3; ++c) *o++ = static_cast<uint8_t>((a[c] + a[c + 3] + b[c] + b[c + 3] + 2) / 4);
  }
  return out;
}

class Grader {
 public:
  explicit Grader(const GradeOptions& o) : opts_(o) {}
  Grader(const Grader&) = delete;
  Grader& operator=(const Grader&) = delete;
  /// The temporary folder goes whichever way grading ended.
  ~Grader() {
    std::error_code ec;
    if (!temp_.empty()) fs::remove_all(temp_, ec);
  }

  ClassResult run();

 private:
  bool prepare();
  bool fatal(int code, const std::string& message) {
    result_.fatal = message;
    result_.fatalCode = code;
    return false;
  }
  bool checkTeacherPrograms();
  bool findClass();
  Task makeTask(size_t program, const std::string& file, size_t seedIndex, uint64_t seed,
                bool screen, const CommentSpec* spec);
  /// Makes the task's folder and scratch folder with what the program may see; "" or why not.
  std::string materialize(const Task& task) const;
  /// Where a program's copy goes in its scratch folder: the student's folder it is in (copied
  /// whole), or "" when it is copied alone; and its path in the scratch folder.
  std::pair<std::string, std::string> layoutOf(const std::string& program) const;
  /// The text of program `index` as graded (SIZE_MAX: the solution).
  const std::string& sourceOf(size_t index) const { return index == SIZE_MAX ? solutionSource_ : sources_[index]; }
  RunOutcome collect(const Task& task, const JobOutcome& outcome) const;
  void finishProgram(size_t index);
  /// `screen`: the first run's final screen as an image (made once, when first asked for).
  void writePicture(ProgramResult& result, const std::vector<RunOutcome>& runs,
                    const std::function<std::shared_ptr<const render::RgbImage>()>& screen);
  std::string describeProcess(const JobOutcome& o, const Job& job) const;
  LimitNames commentLimits(const CommentSpec& spec) const;
  FilteredArgs commentArgs(const CommentSpec& spec, const std::string& program) const;
  /// The time limit of a comment-mode run: the comment's, capped unless trusted; --timeout wins.
  double commentTimeout(const CommentSpec& spec) const {
    return opts_.timeout.value_or(opts_.trustComments ? spec.timeout : std::min(spec.timeout, kCommentTimeoutCap));
  }
  /// The jobs run as runJobs runs them, or one at a time through GradeOptions::runJob.
  int runAll(const std::vector<Job>& jobs, int parallel, const std::function<void(size_t, const JobOutcome&)>& done,
             const std::function<std::string(size_t)>& start) const {
    if (!opts_.runJob) return runJobs(jobs, parallel, done, start);
    for (size_t i = 0; i < jobs.size(); ++i) {
      std::string why = start(i);
      JobOutcome outcome;
      if (why.empty()) {
        outcome = opts_.runJob(jobs[i]);
      } else {
        outcome.kind = JobOutcome::NotStarted;
        outcome.error = why;
      }
      done(i, outcome);
    }
    return 0;
  }
  bool screenWanted() const {
    return assignment_ && (assignment_->needsScreen() || !opts_.picturesDir.empty());
  }

  const GradeOptions& opts_;
  ClassResult result_;
  std::optional<Assignment> assignment_;
  References refs_;
  std::string temp_;
  size_t taskCount_ = 0;
  std::vector<std::string> programs_;           ///< the programs to run (result_ index = same)
  /// Each program's text, read once before any run: what runs, what similarity compares and
  /// what reports show, whatever a run does afterwards.
  std::vector<std::string> sources_;
  std::vector<bool> sourceRead_;  ///< false: sources_ holds why it could not be read
  std::string solutionSource_;
  /// The program's unique report name.
  std::string nameOf(const std::string& program) const {
    std::error_code ec;
    auto it = reportNames_.find(fs::weakly_canonical(program, ec).string());
    return it != reportNames_.end() ? it->second : reportName(program, opts_.paths);
  }
  /// Folders the roster names (canonical): each is a student's folder.
  std::vector<std::string> rosterFolders_;
  /// Every class file's report name (canonical path -> unique name), over the whole class.
  std::map<std::string, std::string> reportNames_;
  std::vector<ProgramResult> extra_;            ///< files not graded, students missing
  std::map<std::string, std::string> students_; ///< canonical program path -> student
  std::vector<std::optional<CommentSpec>> specs_;
  std::vector<std::vector<RunOutcome>> runs_;
  std::vector<size_t> pending_;  ///< runs still to come, per program
  std::shared_ptr<const render::RgbImage> solutionImage_;  ///< the solution's screen, for pictures
  PicturePainter painter_;  ///< the pictures' fonts, loaded once
  size_t finished_ = 0, toGrade_ = 0;
};

std::string Grader::describeProcess(const JobOutcome& o, const Job& job) const {
  std::string text = describe(o, job);
  if (o.kind == JobOutcome::TimedOut) {
    // The run had --timeout and did not stop itself by then (one statement ran long): say both.
    char buf[200];
    std::snprintf(buf, sizeof buf, "did not finish: killed after %g s (the time limit is %s)", wallLimit(job),
                  assignment_ ? refs_.limits.time.c_str() : "the run's --timeout, doubled for rb check and the run");
    text = buf;
  }
  if (o.kind == JobOutcome::Signalled && job.memoryBytes && !memoryLimitUnsupported() &&
      (o.signal == SIGABRT || o.signal == SIGSEGV || o.signal == SIGBUS))
    text += "; perhaps out of memory (the limit is " + std::to_string(job.memoryBytes >> 20) + " MB)";
  return text;
}

LimitNames Grader::commentLimits(const CommentSpec& spec) const {
  LimitNames n;
  for (size_t i = 0; i + 1 < spec.args.size(); ++i)
    if (spec.args[i] == "--max-steps") n.steps = "// args: --max-steps " + spec.args[i + 1];
  if (opts_.maxSteps) n.steps = "rb test --max-steps " + std::to_string(*opts_.maxSteps);
  if (opts_.timeout) n.time = "rb test --timeout " + number(*opts_.timeout);
  else if (spec.timeoutSet) n.time = "// timeout: " + number(std::min(spec.timeout, opts_.trustComments ? spec.timeout : kCommentTimeoutCap));
  else n.time = "the default of " + number(spec.timeout) + " s";
  for (size_t i = 0; i + 1 < spec.args.size(); ++i)
    if (spec.args[i] == "--timeout" && !opts_.timeout) n.time = "// args: --timeout " + spec.args[i + 1];
  return n;
}

FilteredArgs Grader::commentArgs(const CommentSpec& spec, const std::string& program) const {
  FilteredArgs out;
  std::error_code ec;
  std::string home = fs::weakly_canonical(fs::absolute(program, ec).parent_path(), ec).string() + "/";
  const std::vector<std::string>& a = spec.args;
  auto ignored = [&](const std::string& option, const std::string& why) {
    out.notes.push_back("ignored // args: " + option + ": " + why);
  };
  const std::string grant = "only the person running rb test may grant it (rb test --trust-comments)";
  if (!opts_.trustComments && spec.timeoutSet && spec.timeout > kCommentTimeoutCap && !opts_.timeout)
    out.notes.push_back("// timeout: " + number(spec.timeout) + " counts as " + number(kCommentTimeoutCap) +
                        " s: a comment may lower the time limit, not raise it (rb test --timeout or "
                        "--trust-comments may)");
  // What `// args:` may say at all: rb run's documented options. An allowlist: anything else,
  // rb's own options for its jobs above all (--record, --screen, --world, --box...), is left out.
  static const std::set<std::string> takesValue = {"--seed", "--max-steps", "--timeout", "--max-memory", "--events",
                                                   "--keys", "--port", "--baud", "--robot-timeout", "--allow-files",
                                                   "--cells", "--color"};
  static const std::set<std::string> flags = {"--quiet", "--tui", "--real", "--allow-spawn"};
  static const std::set<std::string> granted = {"--allow-files", "--allow-spawn", "--port", "--real", "--baud",
                                                "--robot-timeout"};
  for (size_t i = 0; i < a.size(); ++i) {
    std::string name = a[i], value;
    bool inlineValue = false;
    if (size_t eq = name.find('='); name.rfind("--", 0) == 0 && eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      inlineValue = true;
    }
    bool hasValue = takesValue.count(name) != 0;
    if (!hasValue && !flags.count(name)) {
      ignored(a[i], "not an option of rb run a program's comments may give");
      continue;
    }
    if (hasValue && !inlineValue) {
      if (i + 1 >= a.size()) {
        ignored(a[i], "it needs a value");
        continue;
      }
      value = a[++i];
    } else if (!hasValue && inlineValue) {
      ignored(a[i], "it takes no value");
      continue;
    }
    std::string shown = name + (hasValue ? " " + value : "");
    auto keep = [&](const std::string& v) {
      out.args.push_back(name);
      if (hasValue) out.args.push_back(v);
    };
    if (name == "--events" && !opts_.trustComments) {
      // Copied beside the program into its scratch folder (makeTask), named as written.
      fs::path f = fs::weakly_canonical(fs::absolute(fs::path(program).parent_path() / value, ec), ec);
      if (f.string().rfind(home, 0) == 0 && fs::is_regular_file(f, ec)) keep(value);
      else ignored(shown, "the events file is outside the program's folder");
    } else if (opts_.trustComments) {
      keep(value);
    } else if (granted.count(name)) {
      ignored(shown, grant);
    } else if (name == "--timeout") {
      std::optional<double> t = numberArg(value);
      if (t && *t > 0 && *t <= commentTimeout(spec)) keep(value);
      else ignored(shown, "a comment may lower the time limit, not raise it or switch it off");
    } else if (name == "--max-steps") {
      std::optional<double> n = numberArg(value);
      if (n && *n >= 1 && (!opts_.maxSteps || *n <= static_cast<double>(*opts_.maxSteps))) keep(value);
      else ignored(shown, "a comment may lower the step limit, not raise it or switch it off");
    } else if (name == "--max-memory") {
      std::optional<double> m = numberArg(value);
      if (m && *m >= 1 && *m <= kCommentMemoryCapMb) keep(value);
      else ignored(shown, "a comment may lower the memory limit, not raise it or switch it off");
    } else {
      keep(value);  // --seed, --keys, --tui, --cells, --color, --quiet: nothing more to reach
    }
  }
  return out;
}

std::pair<std::string, std::string> Grader::layoutOf(const std::string& program) const {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(program, ec), ec);
  auto under = [&](const fs::path& folder) -> std::optional<std::string> {
    fs::path rel = p.lexically_relative(folder);
    if (rel.empty() || rel.native().rfind("..", 0) == 0) return std::nullopt;
    return rel.string();
  };
  // A folder the roster names is that student's.
  for (const std::string& folder : rosterFolders_)
    if (std::optional<std::string> rel = under(folder))
      return {folder, (fs::path(folder).filename() / *rel).string()};
  // A class folder with one folder per student: the folder below the class folder.
  for (const std::string& root : opts_.paths) {
    if (!fs::is_directory(root, ec)) continue;
    fs::path r = fs::weakly_canonical(fs::absolute(root, ec), ec);
    std::optional<std::string> rel = under(r);
    if (!rel) continue;
    fs::path relPath(*rel);
    if (std::distance(relPath.begin(), relPath.end()) >= 2) return {(r / *relPath.begin()).string(), *rel};
  }
  return {"", p.filename().string()};
}

Task Grader::makeTask(size_t program, const std::string& file, size_t seedIndex, uint64_t seed,
                      bool screen, const CommentSpec* spec) {
  Task t;
  t.program = program;
  t.seedIndex = seedIndex;
  t.seed = seed;
  t.screen = screen;
  t.dir = temp_ + "/" + std::to_string(taskCount_++);
  std::string base = t.dir + "/";
  t.record = base + "record.json";
  t.screenFile = screen ? base + "screen.runs" : "";
  Job& job = t.job;
  job.argv = opts_.childCommand;
  job.argv.insert(job.argv.end(), {"--record", t.record});
  // Serial ports only when the person running rb test grants them.
  if (spec ? opts_.trustComments : assignment_->ports) job.argv.push_back("--ports");
  if (screen) job.argv.insert(job.argv.end(), {"--screen", t.screenFile});
  if (!opts_.replayFormat.empty() && seedIndex == 0 && program != SIZE_MAX) {
    t.replayFile = base + "replay." + opts_.replayFormat;
    job.argv.insert(job.argv.end(), {"--replay", t.replayFile});
  }
  if (opts_.requireSandbox) job.argv.push_back("--require-sandbox");
  job.stdoutPath = base + "out";
  job.stderrPath = base + "err";
  job.fileBytes = kFileLimit;
  fs::path path = fs::absolute(file);
  // Programs graded by their trusted comments run where they are (the person running rb test
  // vouches for them, as rb run would run them); every other program runs in a scratch folder
  // of its own with copies of what it may see.
  bool inPlace = spec && opts_.trustComments;
  std::string runName = path.filename().string();
  if (inPlace) {
    job.cwd = path.parent_path().string();
    job.env = jobEnvironment(std::getenv("HOME") ? std::getenv("HOME") : job.cwd);
  } else {
    t.box = base + "box";
    // The solution runs alone (with its includes), whatever folder it is in.
    auto [student, rel] = program == SIZE_MAX ? std::pair<std::string, std::string>{"", path.filename().string()}
                                              : layoutOf(file);
    t.studentFolder = student;
    t.mainRel = rel;
    fs::path relDir = fs::path(rel).parent_path();
    job.cwd = (fs::path(t.box) / relDir).string();
    job.argv.insert(job.argv.end(), {"--box", t.box});
    job.env = jobEnvironment(t.box);
    if (student.empty()) {
      // A program copied alone takes the files it #includes from its folder along.
      if (opts_.includedFiles) {
        std::error_code ec;
        fs::path home = fs::weakly_canonical(path.parent_path(), ec);
        for (const std::string& inc : opts_.includedFiles(file)) {
          fs::path r = fs::path(inc).lexically_relative(home);
          if (!r.empty() && r.native().rfind("..", 0) != 0) t.copies.push_back({inc, (relDir / r).string()});
        }
      }
    }
    if (assignment_)
      for (const std::string& f : assignment_->files)
        t.copies.push_back({f, (relDir / fs::path(f).filename()).string()});
  }
  std::vector<std::string> stdinLines;
  if (spec) {
    for (size_t i = 0; i < spec->checkArgs.size(); ++i)
      if (spec->checkArgs[i] == "--target=rb9" ||
          (spec->checkArgs[i] == "--target" && i + 1 < spec->checkArgs.size() && spec->checkArgs[i + 1] == "rb9"))
        job.argv.insert(job.argv.end(), {"--check-target", "rb9"});
    for (const std::string& a : spec->checkArgs)
      if (a == "--portable") job.argv.push_back("--check-portable");
    std::vector<std::string> args = commentArgs(*spec, file).args;
    // The events file a comment names lies in the program's folder: it goes along.
    if (!inPlace)
      for (size_t i = 0; i + 1 < args.size(); ++i)
        if (args[i] == "--events") {
          std::error_code ec;
          fs::path from = fs::weakly_canonical(path.parent_path() / args[i + 1], ec);
          fs::path rel = from.lexically_relative(fs::weakly_canonical(path.parent_path(), ec));
          t.copies.push_back({from.string(), (fs::path(t.mainRel).parent_path() / rel).string()});
        }
    job.argv.insert(job.argv.end(), args.begin(), args.end());
    if (!hasOption(args, "--seed")) job.argv.insert(job.argv.end(), {"--seed", std::to_string(seed)});
    if (opts_.maxSteps && !hasOption(args, "--max-steps"))
      job.argv.insert(job.argv.end(), {"--max-steps", std::to_string(*opts_.maxSteps)});
    // A comment may narrow the time limit, never widen it past the default, unless the person
    // running rb test trusts the comments or sets --timeout.
    double timeout = commentTimeout(*spec);
    // The run stops itself at its time limit and says where; the kill is the backstop.
    if (!hasOption(args, "--timeout")) job.argv.insert(job.argv.end(), {"--timeout", number(timeout)});
    // As rb check and rb run each had the time limit, the child that does both gets twice it.
    job.timeoutSeconds = 2 * timeout + 1;
    job.memoryBytes = kCommentMemoryMb << 20;
    stdinLines = spec->stdinLines;
  } else {
    const Assignment& a = *assignment_;
    for (const Check* c : allChecks(a))
      if (c->kind == Check::Clean && !c->target.empty()) {
        job.argv.insert(job.argv.end(), {"--check-target", c->target});
        break;
      }
    double timeout = opts_.timeout.value_or(a.timeout);
    job.argv.insert(job.argv.end(), {"--seed", std::to_string(seed)});
    job.argv.insert(job.argv.end(), {"--max-steps", std::to_string(opts_.maxSteps.value_or(a.maxSteps))});
    job.argv.insert(job.argv.end(), {"--timeout", number(timeout)});
    job.argv.insert(job.argv.end(), {"--max-memory", std::to_string(a.memoryMb)});
    if (a.spawn) job.argv.push_back("--allow-spawn");
    if (!a.events.empty()) job.argv.insert(job.argv.end(), {"--events", a.events});
    if (!a.keys.empty()) job.argv.insert(job.argv.end(), {"--keys", a.keys});
    if (!a.world.empty()) job.argv.insert(job.argv.end(), {"--world", a.world});
    for (const std::string& post : a.posts()) job.argv.insert(job.argv.end(), {"--post", post});
    for (uint32_t rgb : a.watchedColours()) {
      char hex[16];
      std::snprintf(hex, sizeof hex, "%06X", rgb & 0xFFFFFF);
      job.argv.insert(job.argv.end(), {"--watch-colour", hex});
    }
    // The interpreter stops itself at the timeout and says where; the kill is the backstop for
    // a single statement that never returns.
    job.timeoutSeconds = timeout * 1.5 + 1;
    job.memoryBytes = a.memoryMb << 20;
    stdinLines = a.stdinLines;
  }
  if (!stdinLines.empty()) {
    job.stdinPath = base + "in";
    t.stdinLines = std::move(stdinLines);
  }
  job.argv.insert(job.argv.end(), {"--", inPlace ? runName : fs::path(t.mainRel).filename().string()});
  // Writing the replay of a long run takes about as long as the run: as much time again for
  // it, so that asking for --html never turns a finished program into a timed-out one.
  if (!t.replayFile.empty()) job.reportSeconds = job.timeoutSeconds;
  return t;
}

std::string Grader::materialize(const Task& t) const {
  std::error_code ec;
  if (!fs::create_directory(t.dir, ec) || ec) return "cannot make " + t.dir + ": " + ec.message();
  fs::permissions(t.dir, fs::perms::owner_all, ec);
  if (!t.stdinLines.empty()) {
    std::ofstream in(t.job.stdinPath, std::ios::binary);
    for (const std::string& line : t.stdinLines) in << line << '\n';
    if (!in) return "cannot write " + t.job.stdinPath;
  }
  if (t.box.empty()) return "";
  fs::create_directory(t.box, ec);
  fs::permissions(t.box, fs::perms::owner_all, ec);
  CopyBudget budget;
  std::string error;
  const fs::path box(t.box);
  fs::path main = box / t.mainRel;
  if (!t.studentFolder.empty()) {
    fs::path skip = fs::weakly_canonical(t.program == SIZE_MAX ? *assignment_->solution : programs_[t.program], ec);
    if (!copyTree(t.studentFolder, box / fs::path(t.mainRel).begin()->string(), skip, budget, error)) return error;
    if (budget.over())
      return "the student's folder " + t.studentFolder + " holds more than " + std::to_string(kScratchBytes >> 20) +
             " MB or " + std::to_string(kScratchEntries) + " files, which rb test copies for every run";
  }
  for (const auto& [from, to] : t.copies) {
    bool ok = fs::is_directory(from, ec) ? copyTree(from, box / to, {}, budget, error)
                                         : copyOne(from, box / to, budget, error);
    if (!ok) return error;
  }
  if (budget.over())
    return "the files copied beside the program hold more than " + std::to_string(kScratchBytes >> 20) + " MB";
  // The program itself, as read before any run.
  fs::create_directories(main.parent_path(), ec);
  std::ofstream out(main, std::ios::binary | std::ios::trunc);
  const std::string& text = sourceOf(t.program);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) return "cannot write " + main.string();
  return "";
}

RunOutcome Grader::collect(const Task& t, const JobOutcome& outcome) const {
  RunOutcome run;
  run.seed = t.seed;
  run.process = outcome;
  run.processText = describeProcess(outcome, t.job);
  run.output = readCapped(t.job.stdoutPath, kOutputCap, &run.outputCut);
  run.errors = readCapped(t.job.stderrPath, kOutputCap);
  if (assignment_) {
    // rb run names the limits by its own options; the student's limits are the assignment's.
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"(the --max-steps limit)", "(" + refs_.limits.steps + ")"},
                                   {"(the --timeout limit)", "(" + refs_.limits.time + ")"}})
      for (size_t at = run.errors.find(from); at != std::string::npos; at = run.errors.find(from, at + to.size()))
        run.errors.replace(at, from.size(), to);
  }
  std::error_code ec;
  if (fs::exists(t.record, ec)) {
    // A child killed at its limit leaves the record it wrote before the run: rb check's part.
    std::string text = readCapped(t.record, kFileLimit);
    run.record = recordFromJson(text, run.recordError);
    if (run.record && outcome.kind != JobOutcome::Exited && run.record->complete) run.record.reset();
    if (run.record && outcome.kind == JobOutcome::Exited && !run.record->complete) {
      run.record.reset();
      run.recordError = "an incomplete record";
    }
  } else {
    run.recordError = "no record";
  }
  if (run.record && run.record->screen && t.screen) {
    std::string error;
    run.screen = readScreenFile(t.screenFile, error);
  }
  if (!t.replayFile.empty() && fs::exists(t.replayFile, ec)) {
    // Kept until the program's reports are written; the run's folder goes now.
    std::string kept = t.dir + ".replay";
    fs::rename(t.replayFile, kept, ec);
    if (!ec) run.replayFile = kept;
  }
  fs::remove_all(t.dir, ec);
  return run;
}

bool Grader::checkTeacherPrograms() {
  const Assignment& a = *assignment_;
  std::vector<std::pair<std::string, std::string>> programs;  // file, role
  if (!a.world.empty()) programs.push_back({a.world, "the world program"});
  for (const std::string& p : a.posts()) programs.push_back({p, "a post program"});
  for (const auto& [file, role] : programs) {
    if (!opts_.compileProgram) break;
    std::string error = opts_.compileProgram(file);
    if (!error.empty()) return fatal(64, error + " (" + role + " of " + opts_.assignmentPath + ")");
  }
  return true;
}

bool Grader::findClass() {
  std::vector<std::string> skip;
  if (assignment_) {
    const Assignment& a = *assignment_;
    skip.push_back(a.path);
    for (const std::string* f : {&a.world, &a.roster, &a.events})
      if (!f->empty()) skip.push_back(*f);
    if (a.solution) skip.push_back(*a.solution);
    if (!opts_.roster.empty()) skip.push_back(opts_.roster);
    for (const Check* c : allChecks(a)) {
      if (!c->program.empty()) skip.push_back(c->program);
      if (!c->picture.empty()) skip.push_back(c->picture);
    }
  }
  std::vector<std::string> found;
  std::vector<std::pair<std::string, std::string>> others;
  try {
    if (assignment_) {
      ClassFiles files = findClassFiles(opts_.paths, opts_.include, skip);
      found = std::move(files.programs);
      others = std::move(files.others);
    } else {
      found = findPrograms(opts_.paths, &others);
    }
  } catch (const std::runtime_error& e) {
    return fatal(opts_.include.empty() ? 66 : 64, e.what());
  }
  if (found.empty() && others.empty()) return fatal(66, "no programs to grade (no .bas files)");

  // Sharding: programs and other files together, by their sorted paths.
  std::vector<std::string> all = found;
  for (const auto& o : others) all.push_back(o.first);
  std::sort(all.begin(), all.end());
  reportNames_ = uniqueReportNames(all, opts_.paths);
  std::vector<std::string> mine = shardOf(all, opts_.shard, opts_.shards);
  std::set<std::string> inShard(mine.begin(), mine.end());
  for (const std::string& p : found)
    if (inShard.count(p)) programs_.push_back(p);
  for (const auto& [path, why] : others) {
    if (!inShard.count(path)) continue;
    ProgramResult r;
    r.program = path;
    r.name = nameOf(path);
    r.verdict = "fail";
    r.isProgram = false;
    r.reason = why;
    // A file that is not a program but is one of the class's (square.bas.txt): its text for the
    // teacher's report. Never through a link, a FIFO or a device.
    std::error_code ec;
    if (fs::is_regular_file(fs::symlink_status(path, ec))) {
      std::string text, unread;
      if (readSnapshot(path, text, unread)) {
        r.source = std::move(text);
        r.sourceRead = true;
      }
    }
    extra_.push_back(r);
  }

  // The roster: names, and students without a submission.
  std::string rosterPath = !opts_.roster.empty() ? opts_.roster : assignment_ ? assignment_->roster : "";
  if (rosterPath.empty()) return true;
  std::vector<RosterEntry> roster;
  try {
    roster = readRoster(rosterPath);
  } catch (const std::runtime_error& e) {
    return fatal(64, e.what());
  }
  std::error_code ec;
  size_t present = 0;
  for (const RosterEntry& e : roster) {
    fs::path full = fs::weakly_canonical(e.full, ec);
    if (fs::is_directory(full, ec)) rosterFolders_.push_back(full.string());
    bool any = false;
    for (const std::string& p : all) {
      fs::path cp = fs::weakly_canonical(p, ec);
      bool match = cp == full;
      if (!match && fs::is_directory(full, ec)) {
        std::string prefix = full.string() + "/";
        match = cp.string().rfind(prefix, 0) == 0;
      }
      if (match) {
        students_[cp.string()] = e.student;
        any = true;
      }
    }
    if (!any) {
      // Saved under another name by an editor (square.bas.txt for square.bas): that file is
      // the student's, whether it is graded (--include '*.bas.txt') or listed as not graded.
      // Looked for in the whole class, so that every shard agrees on who is missing.
      std::string stem = full.string() + ".";
      for (const std::string& p : all) {
        std::string cp = fs::weakly_canonical(p, ec).string();
        if (cp.rfind(stem, 0) == 0 && !students_.count(cp)) {
          students_[cp] = e.student;
          any = true;
        }
      }
    }
    if (any) {
      ++present;
    } else if (opts_.shard == 1) {
      ProgramResult r;
      r.program = e.path;
      r.student = e.student;
      r.verdict = "missing";
      r.reason = "no submission: " + e.path + " is not in the class folder (" + rosterPath + " line " +
                 std::to_string(e.line) + ")";
      extra_.push_back(r);
    }
  }
  if (present == 0 && !roster.empty())
    return fatal(64, rosterPath + ": the roster names no file or folder that is being graded (the first is '" +
                         roster[0].path + "', line " + std::to_string(roster[0].line) +
                         "): are its paths relative to the roster's folder?");
  for (ProgramResult& r : extra_)
    if (r.student.empty()) {
      auto it = students_.find(fs::weakly_canonical(r.program, ec).string());
      if (it != students_.end()) r.student = it->second;
    }
  return true;
}

bool Grader::prepare() {
  if (!opts_.assignmentPath.empty()) {
    std::string error;
    assignment_ = loadAssignment(opts_.assignmentPath, error);
    if (!assignment_) return fatal(64, error);
    result_.title = assignment_->title;
    result_.assignment = true;
    result_.maxPoints = assignment_->maxPoints();
    for (const Check& c : assignment_->checks) {
      std::optional<Screen> picture;
      if (c.kind == Check::Screen) {
        std::string error2;
        std::optional<render::RgbImage> png = render::readPngFile(c.picture, error2);
        if (!png) return fatal(66, opts_.assignmentPath + ": " + error2);
        picture = screenOf(*png);
      }
      refs_.pictures.push_back(std::move(picture));
    }
    if (!checkTeacherPrograms()) return false;
    // How limits are named in messages: as whoever set them wrote them.
    const Assignment& a = *assignment_;
    std::string file = fs::path(a.path).filename().string();
    refs_.limits.steps = opts_.maxSteps ? "rb test --max-steps " + std::to_string(*opts_.maxSteps)
                         : a.maxStepsSet ? "max-steps = " + std::to_string(a.maxSteps) + " in " + file
                                         : "max-steps, by default " + std::to_string(a.maxSteps);
    refs_.limits.time = opts_.timeout ? "rb test --timeout " + number(*opts_.timeout)
                        : a.timeoutSet ? "timeout = " + number(a.timeout) + " in " + file
                                       : "timeout, by default " + number(a.timeout) + " s";
  }
  if (!findClass()) return false;
  if (assignment_ && assignment_->solution) {
    std::error_code ec;
    fs::path sol = fs::weakly_canonical(*assignment_->solution, ec);
    programs_.erase(std::remove_if(programs_.begin(), programs_.end(),
                                   [&](const std::string& p) { return fs::weakly_canonical(p, ec) == sol; }),
                    programs_.end());
    std::string why;
    if (!readSnapshot(*assignment_->solution, solutionSource_, why))
      return fatal(66, "cannot read the solution " + *assignment_->solution + ": " + why);
  }
  // Every program's text, once, before anything runs (a program that renames a decoy over its
  // own file changes nothing that is graded or shown).
  sources_.resize(programs_.size());
  sourceRead_.assign(programs_.size(), false);
  for (size_t p = 0; p < programs_.size(); ++p) {
    std::string why;
    sourceRead_[p] = readSnapshot(programs_[p], sources_[p], why);
    if (!sourceRead_[p]) sources_[p] = why;
  }

  std::string pattern = (fs::temp_directory_path() / "rb-test-XXXXXX").string();
  if (!mkdtemp(pattern.data())) return fatal(74, "cannot make a temporary folder: " + std::string(std::strerror(errno)));
  temp_ = pattern;
  if (!opts_.picturesDir.empty()) {
    std::string error;
    if (!render::makeFolder(opts_.picturesDir, error)) return fatal(74, error);
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
  if (assignment_ && assignment_->solution) {
    std::vector<Task> tasks;
    std::vector<Job> jobs;
    for (size_t s = 0; s < assignment_->seeds.size(); ++s) {
      tasks.push_back(makeTask(SIZE_MAX, *assignment_->solution, s, assignment_->seeds[s],
                               assignment_->needsScreen() || pictures, nullptr));
      jobs.push_back(tasks.back().job);
    }
    refs_.solution.resize(tasks.size());
    result_.interruptedBy = runAll(
        jobs, parallel, [&](size_t i, const JobOutcome& o) { refs_.solution[i] = collect(tasks[i], o); },
        [&](size_t i) { return materialize(tasks[i]); });
    if (result_.interruptedBy) return result_;
    for (const RunOutcome& s : refs_.solution) {
      std::string why = unrunnable(s);
      if (why.empty() && s.record) why = s.record->worldError;
      if (why.empty() && s.record) why = stopDescription(*s.record, refs_.limits);
      if (why.empty() && s.record)
        for (size_t i = 0; i < s.record->posts.size(); ++i)
          if (s.record->posts[i].error)
            why = "the post program " + s.record->posts[i].file + " fails on it: line " +
                  std::to_string(s.record->posts[i].error->line) + ": " + s.record->posts[i].error->message;
      if (!why.empty()) {
        result_.fatal = "the solution " + *assignment_->solution + " does not run cleanly" +
                        (refs_.solution.size() > 1 ? " with seed " + std::to_string(s.seed) : "") + ": " + why;
        result_.fatalCode = 1;
        fs::remove_all(temp_);
        return result_;
      }
    }
  }
  if (assignment_) {
    bool solutionMoves = false;
    for (const RunOutcome& s : refs_.solution) solutionMoves = solutionMoves || (s.record && s.record->moves > 0);
    refs_.aboutRobot = assignment_->aboutRobot.value_or(assignment_->robotChecks() || solutionMoves);
    // The solution graded by its own assignment: a teacher's post check it fails is a mistake
    // in the assignment (every student would fail it too); any other check it fails is said.
    if (!refs_.solution.empty()) {
      Grading own = checkAssignment(*assignment_, refs_, refs_.solution);
      for (size_t i = 0; i < own.checks.size(); ++i) {
        const CheckResult& c = own.checks[i];
        if (c.passed || !c.checked) continue;
        std::string what = "the solution fails its own check '" + c.name + "': " + c.message;
        if (assignment_->checks[i].kind == Check::Post) {
          result_.fatal = what;
          result_.fatalCode = 1;
          fs::remove_all(temp_);
          return result_;
        }
        result_.warnings.push_back(what);
      }
      if (!own.gate.empty()) result_.warnings.push_back("the solution earns nothing: " + own.gate);
    }
  }

  // The class.
  result_.programs.resize(programs_.size());
  specs_.resize(programs_.size());
  runs_.resize(programs_.size());
  pending_.assign(programs_.size(), 0);
  std::vector<Task> tasks;
  std::error_code ec;
  for (size_t p = 0; p < programs_.size(); ++p) {
    ProgramResult& r = result_.programs[p];
    r.program = programs_[p];
    r.name = nameOf(programs_[p]);
    auto student = students_.find(fs::weakly_canonical(programs_[p], ec).string());
    if (student != students_.end()) r.student = student->second;
    if (!sourceRead_[p]) {
      r.verdict = "error";
      r.reason = "cannot read " + programs_[p] + ": " + sources_[p];
      sources_[p].clear();
      continue;
    }
    r.source = sources_[p];
    r.sourceRead = true;
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
      if (!specs_[p]->problems.empty()) {
        // Malformed expectations cannot be met: the program is not run (a `// timeout:` that
        // cannot be read must not leave a runaway to the default limit).
        r.verdict = "fail";
        r.reason = specs_[p]->problems.front() + " (the program was not run)";
        for (const std::string& problem : specs_[p]->problems) {
          CheckResult c;
          c.name = "comments";
          c.message = problem;
          r.checks.push_back(c);
        }
        continue;
      }
      r.notes = commentArgs(*specs_[p], programs_[p]).notes;
      tasks.push_back(makeTask(p, programs_[p], 0, opts_.seed, opts_.screens && !opts_.picturesDir.empty(), &*specs_[p]));
      pending_[p] = 1;
    } else {
      for (size_t s = 0; s < assignment_->seeds.size(); ++s)
        tasks.push_back(makeTask(p, programs_[p], s, assignment_->seeds[s], screenWanted(), nullptr));
      pending_[p] = assignment_->seeds.size();
    }
    runs_[p].resize(pending_[p]);
    ++toGrade_;
  }
  std::vector<Job> jobs;
  for (const Task& t : tasks) jobs.push_back(t.job);
  result_.interruptedBy = runAll(
      jobs, parallel,
      [&](size_t i, const JobOutcome& o) {
        const Task& t = tasks[i];
        runs_[t.program][t.seedIndex] = collect(t, o);
        if (--pending_[t.program] == 0) finishProgram(t.program);
      },
      [&](size_t i) { return materialize(tasks[i]); });
  if (result_.interruptedBy) return result_;
  fs::remove_all(temp_, ec);

  for (ProgramResult& r : extra_) {
    r.maxPoints = assignment_ ? assignment_->maxPoints() : 0;
    result_.programs.push_back(std::move(r));
  }
  std::stable_sort(result_.programs.begin(), result_.programs.end(), [](const ProgramResult& a, const ProgramResult& b) {
    bool am = a.verdict == "missing", bm = b.verdict == "missing";
    if (am != bm) return bm;
    return a.program < b.program;
  });
  for (const ProgramResult& r : result_.programs) {
    if (r.verdict == "pass") ++result_.passed;
    else if (r.verdict == "skip") ++result_.skipped;
    else if (r.verdict == "error") ++result_.errors;
    else if (r.verdict == "missing") ++result_.missing;
    else ++result_.failed;
  }
  if (opts_.similarity) {
    // The programs graded (the solution and teacher files excluded, as from grading).
    SimilarityOptions so;
    so.ignore = opts_.similarityIgnore;
    // The texts as graded, not as the files may be now.
    std::map<std::string, size_t> index;
    for (size_t p = 0; p < programs_.size(); ++p) index[programs_[p]] = p;
    so.source = [&](const std::string& path) -> std::optional<std::string> {
      auto it = index.find(path);
      if (it == index.end() || !sourceRead_[it->second]) return std::nullopt;
      return sources_[it->second];
    };
    result_.similarity = findSimilar(programs_, so);
  }
  result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result_;
}

void Grader::finishProgram(size_t index) {
  ProgramResult& r = result_.programs[index];
  std::vector<RunOutcome>& runs = runs_[index];
  if (assignment_) {
    Grading g = checkAssignment(*assignment_, refs_, runs);
    r.checks = std::move(g.checks);
    r.gate = std::move(g.gate);
  } else {
    r.checks = checkComments(*specs_[index], runs[0], commentLimits(*specs_[index]));
  }
  r.verdict = r.gate.empty() ? "pass" : "fail";
  r.reason = r.gate;
  for (const CheckResult& c : r.checks) {
    r.maxPoints += c.points;
    r.points += c.earned;
    if (!c.passed && r.verdict == "pass") {
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
  for (const RunOutcome& run : runs)
    if (run.record && !run.record->confinement.empty() && result_.confinement.empty())
      result_.confinement = run.record->confinement;
  const RunOutcome& first = runs[0];
  if (first.record) {
    r.steps = first.record->steps;
    for (const RunRecord::InputMark& m : first.record->inputs)
      if (m.end <= kReportCap) r.inputs.push_back(m);
  }
  r.output = first.output.substr(0, kReportCap);
  r.errors = first.errors.substr(0, kReportCap);
  if (first.record) r.marks = lineMarks(*first.record, r.program);
  // A program that did not compile (or run) has no picture: there is nothing of its own to show.
  const bool ran = first.record && first.record->status != "rejected" && first.record->status != "not-run";
  std::shared_ptr<const render::RgbImage> shown;  // the first run's final screen, made once
  auto screenImage = [&]() {
    if (!shown && first.screen) shown = std::make_shared<const render::RgbImage>(imageOf(*first.screen));
    return shown;
  };
  if (!opts_.picturesDir.empty() && ran) writePicture(r, runs, screenImage);
  if (opts_.screens && !opts_.picturesDir.empty() && first.screen && ran) {
    fs::path to = fs::path(opts_.picturesDir) / fs::path(r.name).replace_extension(".screen.png");
    std::string error;
    if (render::writePngFile(to.string(), halfSize(*screenImage()), error)) r.screen = to.string();
    else result_.writeErrors.push_back(error);
  }
  if (!first.replayFile.empty()) {
    // Written as every other report file is (a FIFO there is written to, never replaced).
    fs::path to = fs::path(opts_.picturesDir) / fs::path(r.name).replace_extension("." + opts_.replayFormat);
    bool cut = false;
    std::string bytes = readCapped(first.replayFile, kFileLimit, &cut), error;
    if (cut) error = "cannot write '" + to.string() + "': the replay is larger than " + std::to_string(kFileLimit >> 20) + " MB";
    if (!cut && render::writeFileBytes(to.string(), bytes.data(), bytes.size(), error)) r.replay = to.string();
    else result_.writeErrors.push_back(error);
    std::error_code ec;
    fs::remove(first.replayFile, ec);
  }
  for (RunOutcome& run : runs) run.screen.reset();  // a class's screens would not fit in memory
  ++finished_;
  if (opts_.progress) opts_.progress(finished_, toGrade_);
}

void Grader::writePicture(ProgramResult& r, const std::vector<RunOutcome>& runs,
                          const std::function<std::shared_ptr<const render::RgbImage>()>& screen) {
  const RunOutcome& run = runs[0];
  if (!run.record) return;
  PictureInput in;
  in.student = run.record->trail;
  in.robotRadius = run.record->radius;
  in.studentView = opts_.studentPictures;
  if (run.screen && opts_.studentPictures) in.studentScreen = screen();
  in.title = fs::path(r.program).filename().string() + (r.student.empty() ? "" : " (" + r.student + ")");
  if (run.record->located) in.studentEnd = run.record->pos;
  in.studentPath = run.record->path;
  if (!refs_.solution.empty() && refs_.solution[0].record) {
    const RunRecord& sol = *refs_.solution[0].record;
    in.reference = sol.trail;
    if (sol.located) in.referenceEnd = sol.pos;
    if (refs_.solution[0].screen && !opts_.studentPictures) {
      if (!solutionImage_) solutionImage_ = std::make_shared<const render::RgbImage>(imageOf(*refs_.solution[0].screen));
      in.background = solutionImage_;
    }
  } else if (assignment_) {
    // No solution to compare with: the program's own screen behind its path (the world's walls).
    if (run.screen && !opts_.studentPictures) in.background = screen();
    for (const Check* c : allChecks(*assignment_))
      if (c->kind == Check::Trail) {
        in.reference = c->reference;
        break;
      }
  }
  if (assignment_) {
    for (const Check* c : allChecks(*assignment_)) {
      if (c->hidden && opts_.studentPictures) continue;
      if (c->kind == Check::Visits && in.waypoints.empty()) in.waypoints = c->targets;
      if (c->kind == Check::EndsIn || c->kind == Check::Touch || c->kind == Check::Avoid)
        for (const Region& g : c->regions)
          in.regions.push_back({c->kind == Check::Avoid ? PictureRegion::Avoid : PictureRegion::Goal, g, c->name});
      if (c->kind == Check::Touch || c->kind == Check::Avoid)
        for (size_t k = 0; k < c->colours.size(); ++k)
          in.colours.push_back({c->colours[k], c->name == c->colourNames[k] ? c->name : c->name + ": " + c->colourNames[k],
                                c->kind == Check::Avoid});
    }
    // Where each failed check failed (a hidden one's place stays hidden from students).
    for (const CheckResult& c : r.checks)
      if (!c.passed && c.checked && c.at && !(c.hidden && opts_.studentPictures)) in.failures.push_back({*c.at, c.name});
  }
  fs::path out = fs::path(opts_.picturesDir) / fs::path(r.name).replace_extension(".png");
  std::string error;
  if (render::writePngFile(out.string(), painter_.picture(in), error)) {
    r.picture = out.string();
    std::vector<std::string> drawn = painter_.legend(in);
    r.pictureCaption = "Drawn: ";
    for (size_t i = 0; i < drawn.size(); ++i) r.pictureCaption += (i ? "; " : "") + drawn[i];
    r.pictureCaption += drawn.empty() ? "nothing but the screen." : ".";
  } else {
    result_.writeErrors.push_back(error);
  }
}

}  // namespace

namespace {
std::string entryProblem(const fs::directory_entry& entry, const fs::path& root);
}  // namespace

std::vector<std::string> findPrograms(const std::vector<std::string>& paths,
                                      std::vector<std::pair<std::string, std::string>>* others) {
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
      fs::path root = fs::weakly_canonical(fs::absolute(path, ec), ec);
      for (fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
           !ec && it != end; it.increment(ec)) {
        if (lower(it->path().extension().string()) != ".bas") continue;
        std::string why = entryProblem(*it, root);
        if (!why.empty()) {
          if (others) others->push_back({it->path().lexically_normal().string(), why});
          continue;
        }
        if (it->is_regular_file(ec) && !isNontest(it->path())) files.push_back(it->path());
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

namespace {

bool hidden(const fs::path& p) {
  std::string name = p.filename().string();
  return !name.empty() && name[0] == '.';
}

/// Why an entry of a class folder cannot be graded whatever its name, or "": a symbolic link
/// that leads out of the class folder (its text must not reach a report), one that cannot be
/// followed, a FIFO, a socket or a device (reading one could block or never end).
std::string entryProblem(const fs::directory_entry& entry, const fs::path& root) {
  std::error_code ec;
  fs::file_status own = entry.symlink_status(ec);
  if (fs::is_symlink(own)) {
    fs::path target = fs::canonical(entry.path(), ec);
    if (ec) return "not graded: a symbolic link that cannot be followed (" + ec.message() + ")";
    fs::path rel = target.lexically_relative(root);
    if (rel.empty() || rel.native().rfind("..", 0) == 0) return "not graded: a symbolic link that leads out of the class folder";
    fs::file_status st = fs::status(target, ec);
    if (fs::is_regular_file(st) || fs::is_directory(st)) return "";
    own = st;
  }
  if (fs::is_fifo(own)) return "not graded: a FIFO (named pipe), not a program file";
  if (fs::is_socket(own)) return "not graded: a socket, not a program file";
  if (fs::is_character_file(own) || fs::is_block_file(own)) return "not graded: a device, not a program file";
  return "";
}

/// Why a file is not graded: it is not a program (and what it may be instead).
std::string notGraded(const fs::path& p) {
  std::string name = lower(p.filename().string());
  std::string why = "not graded: not a .bas file";
  for (const char* ext : {".bas.txt", ".bas.rtf", ".bas.doc", ".bas.docx", ".bas.bak"})
    if (name.size() > std::strlen(ext) && name.compare(name.size() - std::strlen(ext), std::string::npos, ext) == 0)
      return why + " (saved as " + ext + "? rename it to end in .bas, or grade it with --include '*" + ext + "')";
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".txt") == 0)
    return why + " (a program saved as .txt? rename it to end in .bas, or grade it with --include '*.txt')";
  return why;
}

}  // namespace

ClassFiles findClassFiles(const std::vector<std::string>& paths, const std::vector<std::string>& include,
                          const std::vector<std::string>& skip) {
  ClassFiles out;
  std::set<std::string> seen, skipped;
  std::error_code ec;
  for (const std::string& s : skip) skipped.insert(fs::weakly_canonical(s, ec).string());
  std::vector<size_t> used(include.size(), 0);
  auto included = [&](const fs::path& p) {
    std::string name = p.filename().string();
    bool any = false;
    for (size_t i = 0; i < include.size(); ++i)
      if (fnmatch(include[i].c_str(), name.c_str(), 0) == 0) {
        ++used[i];
        any = true;
      }
    return any;
  };
  auto add = [&](const fs::path& p, bool given) {
    std::string key = fs::weakly_canonical(p, ec).string();
    if (skipped.count(key) || !seen.insert(key).second) return;
    std::string path = p.lexically_normal().string();
    if (lower(p.extension().string()) == ".bas") {
      if (given || !isNontest(p)) out.programs.push_back(path);
    } else if (included(p) || given) {
      // A file named on the command line is graded as the teacher asked.
      out.programs.push_back(path);
    } else {
      out.others.push_back({path, notGraded(p)});
    }
  };
  for (const std::string& path : paths) {
    if (fs::is_directory(path, ec)) {
      std::vector<fs::path> files;
      fs::path root = fs::weakly_canonical(fs::absolute(path, ec), ec);
      fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
      for (; !ec && it != end; it.increment(ec)) {
        if (hidden(it->path())) {
          if (it->is_directory(ec)) it.disable_recursion_pending();
          continue;
        }
        std::string why = entryProblem(*it, root);
        if (!why.empty()) {
          std::string key = fs::absolute(it->path(), ec).lexically_normal().string();
          if (!skipped.count(key) && seen.insert(key).second)
            out.others.push_back({it->path().lexically_normal().string(), why});
          continue;
        }
        if (it->is_regular_file(ec)) files.push_back(it->path());
      }
      std::sort(files.begin(), files.end());
      for (const fs::path& f : files) add(f, false);
    } else if (fs::exists(path, ec)) {
      add(path, true);
    } else {
      throw std::runtime_error(path + ": no such file or folder");
    }
  }
  for (size_t i = 0; i < include.size(); ++i)
    if (!used[i]) throw std::runtime_error("--include '" + include[i] + "' matches no file in the class folder");
  std::sort(out.programs.begin(), out.programs.end());
  std::sort(out.others.begin(), out.others.end());
  return out;
}

std::vector<RosterEntry> readRoster(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the roster");
  std::vector<RosterEntry> out;
  fs::path dir = fs::absolute(path).parent_path();
  std::string line;
  uint32_t number = 0;
  std::set<std::string> students;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0) line.erase(0, 3);
    // Fields as RFC 4180 writes them: commas, quotes around a field that has one.
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
      char c = line[i];
      if (quoted) {
        if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') field += '"', ++i;
        else if (c == '"') quoted = false;
        else field += c;
      } else if (c == '"') {
        quoted = true;
      } else if (c == ',') {
        fields.push_back(field);
        field.clear();
      } else {
        field += c;
      }
    }
    if (quoted) throw std::runtime_error(path + ":" + std::to_string(number) + ": a quote is not closed");
    fields.push_back(field);
    for (std::string& f : fields) {
      while (!f.empty() && (f.back() == ' ' || f.back() == '\t')) f.pop_back();
      while (!f.empty() && (f[0] == ' ' || f[0] == '\t')) f.erase(0, 1);
    }
    if (fields.size() == 1 && fields[0].empty()) continue;  // a blank line
    if (fields[0].rfind("#", 0) == 0) continue;              // a comment
    if (number == 1 && fields.size() >= 2 && lower(fields[0]) == "student") continue;  // the header
    if (fields.size() != 2 || fields[0].empty() || fields[1].empty())
      throw std::runtime_error(path + ":" + std::to_string(number) +
                               ": a roster row is a student and a file or folder: name,file.bas");
    if (!students.insert(fields[0]).second)
      throw std::runtime_error(path + ":" + std::to_string(number) + ": '" + fields[0] + "' is on the roster twice");
    RosterEntry e;
    e.student = fields[0];
    e.path = fields[1];
    fs::path p(fields[1]);
    e.full = (p.is_relative() ? dir / p : p).lexically_normal().string();
    e.line = number;
    out.push_back(e);
  }
  if (out.empty()) throw std::runtime_error(path + ": the roster lists no student");
  return out;
}

std::string reportName(const std::string& program, const std::vector<std::string>& paths) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(program, ec);
  std::string name;
  for (const std::string& root : paths) {
    if (!fs::is_directory(root, ec)) continue;
    fs::path r = fs::weakly_canonical(root, ec);
    fs::path rel = p.lexically_relative(r);
    if (!rel.empty() && rel.native().rfind("..", 0) != 0 && (name.empty() || rel.string().size() < name.size()))
      name = rel.string();
  }
  if (name.empty()) name = p.filename().string();
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

std::map<std::string, std::string> uniqueReportNames(const std::vector<std::string>& files,
                                                      const std::vector<std::string>& paths) {
  std::map<std::string, std::string> out;
  std::map<std::string, std::vector<std::string>> byName;  // lower-case name -> canonical paths
  std::error_code ec;
  for (const std::string& f : files) {
    std::string key = fs::weakly_canonical(f, ec).string();
    std::string name = reportName(f, paths);
    out[key] = name;
    std::vector<std::string>& same = byName[lower(name)];
    if (std::find(same.begin(), same.end(), key) == same.end()) same.push_back(key);
  }
  for (const auto& [name, keys] : byName) {
    if (keys.size() < 2) continue;
    // Names alike (class/x/y.bas and class/x_y.bas, or Ana.bas and ana.bas on a file system
    // that ignores case): each gets a mark of its own path, the same in every run and shard.
    for (const std::string& key : keys) {
      uint64_t h = 14695981039346656037ull;  // FNV-1a
      for (unsigned char c : key) h = (h ^ c) * 1099511628211ull;
      char mark[16];
      std::snprintf(mark, sizeof mark, "~%06llx", static_cast<unsigned long long>(h & 0xFFFFFF));
      fs::path n(out[key]);
      out[key] = n.stem().string() + mark + n.extension().string();
    }
  }
  return out;
}

ClassResult gradeClass(const GradeOptions& options) { return Grader(options).run(); }

}  // namespace rb::grade
