#pragma once
// `rb test`'s engine: finds the programs, runs each in a child process (rb itself, through the
// hidden `rb test-job` command) several at a time, and grades the runs against the programs'
// comments or an assignment file.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "checks.h"
#include "similarity.h"

namespace rb::grade {

struct GradeOptions {
  std::vector<std::string> paths;         ///< files and folders (searched for *.bas)
  std::string assignmentPath;             ///< "" : expectations come from the comments
  int jobs = 0;                           ///< programs at once (0: one per core)
  int shard = 1, shards = 1;              ///< grade only the programs of shard K of N
  uint64_t seed = 1;                      ///< comment mode: the seed when // args gives none
  std::optional<uint64_t> maxSteps;       ///< overrides the assignment's and the comments'
  std::optional<double> timeout;          ///< seconds: overrides the assignment's / // timeout
  std::string picturesDir;                ///< "" : no pictures
  bool studentPictures = false;           ///< pictures for students: no solution drawn
  /// With picturesDir: also a replay of each program's run in this format ("gif", "svg",
  /// "html"), or "" for none.
  std::string replayFormat;
  /// With picturesDir: also each program's final screen at half size (NAME.screen.png, 400 x
  /// 300), as the class report page (rb test --html) shows it.
  bool screens = false;
  /// Assignment mode: file names (globs like "*.txt") graded as programs besides *.bas.
  std::vector<std::string> include;
  std::string roster;                     ///< a roster CSV overriding the assignment's
  /// Comment mode: let `// args:` grant access (--allow-files, --allow-spawn, --port, --real).
  /// Only the person running rb may; rb's own tests do.
  bool trustComments = false;
  /// Also compare the programs with each other (a plagiarism aid): ClassResult::similarity.
  bool similarity = false;
  /// Template files whose code does not count as shared (--similarity-ignore).
  std::vector<std::string> similarityIgnore;
  /// Loads and compiles a teacher's program (world, post): its first error as
  /// "FILE:LINE:COL: message", or "" when it compiles. Unset: not checked before grading.
  std::function<std::string(const std::string& file)> compileProgram;
  /// The files a program #includes from its own folder tree (absolute, canonical), copied
  /// beside it into its scratch folder. Unset: none are.
  std::function<std::vector<std::string>(const std::string& program)> includedFiles;
  /// Refuse to grade when the kernel cannot confine the programs (docs/confinement.md).
  bool requireSandbox = false;
  /// How to start a child that runs one program: rb itself and the hidden subcommand.
  std::vector<std::string> childCommand;
  /// Set: each job runs through it, one at a time, in the grading process itself, with the job's
  /// files as a child would have them (rb test --in-process, the browser's way: a page has no
  /// processes). Only rb's own rules confine such runs (run/sandbox.h), not the kernel's; the
  /// report's confinement says so. Unset: each job runs in a child process (pool.h).
  std::function<JobOutcome(const Job& job)> runJob;
  /// Called as each program is graded (in the order they finish).
  std::function<void(size_t done, size_t total)> progress;
};

struct ProgramResult {
  std::string program;             ///< the path as found
  /// The name rb test gives what it writes about the program (its picture, feedback, page):
  /// reportName()'s, made unique over the class.
  std::string name;
  /// The program's text as graded (read before any run): what similarity compares and what
  /// the reports show. Empty for a file that was not graded.
  std::string source;
  bool sourceRead = false;
  std::string student;             ///< the roster's name for it, or ""
  /// "pass", "fail", "skip", "error" (rb could not grade it) or "missing" (a student on the
  /// roster with no submission). A file that is not a program fails ("not graded: ...").
  std::string verdict;
  std::string reason;              ///< the first failed check's message, or why it was skipped
  std::string gate;                ///< why nothing counts ("the program is empty"), or ""
  /// What rb test did differently from what the program's comments asked, and why ("ignored //
  /// args: --allow-spawn: only the person running rb test may grant it").
  std::vector<std::string> notes;
  std::vector<CheckResult> checks;
  uint64_t steps = 0;              ///< of the first run
  double seconds = 0;              ///< wall time of all its runs
  double points = 0, maxPoints = 0;
  std::string output;              ///< the first run's output (for reports), shortened
  /// Where input's prompts and echoes are in `output` (a transcript's marks).
  std::vector<record::RunRecord::InputMark> inputs;
  std::string errors;              ///< the first run's standard error, shortened
  std::string picture;             ///< the PNG written for it, or ""
  std::string pictureCaption;      ///< what the picture draws, from its legend ("Drawn: your trail; ...")
  std::string replay;              ///< the replay written for it, or ""
  std::string screen;              ///< its final screen's PNG, half size (GradeOptions::screens), or ""
  /// Lines of the program where its first run went wrong: its errors (rb check's, loading's),
  /// the runtime error or the limit that stopped it, in line order.
  struct LineMark {
    uint32_t line = 0;
    std::string message;
  };
  std::vector<LineMark> marks;
  /// False for a file of the class that is not a program (listed with why, never run).
  bool isProgram = true;
};

/// What tells gradings apart, so that rb test --merge knows which reports make one class: rb test
/// sets it, the JSON report carries it.
struct GradingOrigin {
  std::vector<std::string> paths;  ///< the files and folders graded, as given
  int shard = 1, shards = 1;       ///< --shard K/N
  std::string assignmentFile;      ///< as given; "" against the programs' comments
  std::string assignmentDigest;    ///< of the assignment file's bytes (FNV-1a, 16 hex digits)
  std::string rbVersion;           ///< the rb that graded
};

struct ClassResult {
  std::string title;               ///< the assignment's title, or "rb test"
  std::vector<ProgramResult> programs;
  double seconds = 0;              ///< wall time of the whole grading
  size_t passed = 0, failed = 0, skipped = 0, errors = 0, missing = 0;
  bool assignment = false;         ///< graded against an assignment (points and checks)
  /// Reports for students (rb test --student): a hidden check's failure says only that a hidden
  /// check failed.
  bool studentView = false;
  double maxPoints = 0;            ///< the assignment's points
  std::string timestamp;           ///< ISO 8601, UTC, when grading started
  /// Things the teacher should know that do not stop grading ("the solution fails its own check").
  std::vector<std::string> warnings;
  /// Pictures, screens and replays rb test could not write (each names the file and why): rb
  /// test says them and ends with 74.
  std::vector<std::string> writeErrors;
  /// What the kernel could not put in force around the runs (no Landlock...), said once in every
  /// report; "" when every run was confined by the kernel (docs/confinement.md).
  std::string confinement;
  /// Pairs of programs with much code alike (GradeOptions::similarity).
  std::optional<SimilarityReport> similarity;
  GradingOrigin origin;
  // When grading could not happen at all: the message and rb's exit code (64 usage, 66 no
  // input, 74 I/O). 0 otherwise.
  int fatalCode = 0;
  std::string fatal;
  /// The signal (Ctrl-C's SIGINT, SIGTERM, ...) that stopped grading, its programs ended and its
  /// temporary files removed: rb ends by it. 0 otherwise.
  int interruptedBy = 0;
};

ClassResult gradeClass(const GradeOptions& options);

/// The programs `paths` name, as rb test finds them: files as given, folders searched
/// recursively for *.bas (any case), sorted, without files whose first line is `// nontest`.
/// In folders, a *.bas that is a link leading out of the folder, a FIFO or a device is not a
/// program: it goes to `others` (path and why) when given. Throws std::runtime_error naming a
/// path that does not exist.
std::vector<std::string> findPrograms(const std::vector<std::string>& paths,
                                      std::vector<std::pair<std::string, std::string>>* others = nullptr);

/// A class folder as an assignment grades it: every file is accounted for.
struct ClassFiles {
  std::vector<std::string> programs;  ///< *.bas and what `include` names, sorted
  /// Files that are not programs: path and why ("not a .bas file; saved as .bas.txt?").
  std::vector<std::pair<std::string, std::string>> others;
};
/// Folders are searched recursively; hidden files and folders (.git) and `skip` (the
/// assignment's own files) are left out; `include` globs (fnmatch, on the file name) grade
/// more files as programs. Throws std::runtime_error naming a path that does not exist, or
/// an `include` glob that matches no file.
ClassFiles findClassFiles(const std::vector<std::string>& paths, const std::vector<std::string>& include,
                          const std::vector<std::string>& skip);

/// A roster: one student per row, `student,file` (a file or a folder, relative to the roster's
/// folder), a header row `student,file` optional. Throws std::runtime_error "FILE:LINE: ...".
struct RosterEntry {
  std::string student;
  std::string path;   ///< as written
  std::string full;   ///< resolved
  uint32_t line = 0;
};
std::vector<RosterEntry> readRoster(const std::string& path);

/// A file name for what rb test writes about a program (its picture, its feedback): the
/// program's path below the folder given that holds it, '/' turned into '_' ("ana_square.bas"
/// for class/ana/square.bas when class/ was given), without the extension's replacement.
std::string reportName(const std::string& program, const std::vector<std::string>& paths);

/// reportName() for each of `files` (keyed by canonical path), made unique: files whose names
/// would be alike, also but for case, each get a mark made from their path ("x_y~1a2b3c.bas").
std::map<std::string, std::string> uniqueReportNames(const std::vector<std::string>& files,
                                                      const std::vector<std::string>& paths);

/// The programs of shard K of N (1-based): every N-th program starting with the K-th.
std::vector<std::string> shardOf(const std::vector<std::string>& programs, int shard, int shards);

}  // namespace rb::grade
