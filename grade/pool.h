#pragma once
// Runs jobs in child processes, several at a time. Each child gets its own standard input,
// output and error files, a memory limit and a CPU limit (setrlimit), and is killed when it
// runs longer than its wall-clock limit, so a program that crashes, hangs or eats memory costs
// only its own job.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace rb::grade {

struct Job {
  std::vector<std::string> argv;  ///< argv[0] is the executable's path
  std::string cwd;                ///< working folder ("": the parent's)
  std::string stdinPath;          ///< "" reads /dev/null
  std::string stdoutPath;         ///< "" writes to /dev/null
  std::string stderrPath;
  double timeoutSeconds = 30;     ///< wall clock; the child is killed (SIGKILL) after it
  uint64_t memoryBytes = 0;       ///< RLIMIT_AS (0: none)
  uint64_t fileBytes = 0;         ///< RLIMIT_FSIZE: the largest file it may write (0: none)
  /// The child's whole environment ("NAME=value"); empty: the parent's.
  std::vector<std::string> env;
  /// More time, wall clock and processor, after timeoutSeconds, for what the child writes once
  /// the program has run (a replay of a long run): that work is rb's, and a report asked for
  /// must not change whether a program finished in time.
  double reportSeconds = 0;
};

struct JobOutcome {
  enum Kind {
    Exited,      ///< ended by itself with `code`
    Signalled,   ///< killed by `signal` (a crash, or a limit: SIGXCPU, SIGXFSZ)
    TimedOut,    ///< killed after its wall-clock limit
    NotStarted,  ///< fork or exec failed (`error`)
  };
  Kind kind = NotStarted;
  int code = 0;
  int signal = 0;
  double seconds = 0;  ///< wall time from start to end
  std::string error;
};

/// The wall-clock time after which the job is killed: its time limit and the time for reports.
double wallLimit(const Job& job);

/// A short description: "exit 0", "killed by signal 11 (SIGSEGV)", "killed after 10 s".
std::string describe(const JobOutcome& outcome, const Job& job);

/// Runs every job, at most `parallel` at once (at least 1), in order of the list. `start`, when
/// given, is called in the calling process just before a job starts, with its index: it makes
/// what the job needs and returns "" or why the job cannot start (it then ends NotStarted with
/// that error). `done` is called in the calling process as each job ends, with its index.
/// Returns when all ended: 0, or the signal (SIGINT, SIGTERM, SIGHUP, SIGQUIT) that came
/// meanwhile, after ending every running job with its process group (the caller cleans up, then
/// ends by that signal). Each child dies with the calling process (PR_SET_PDEATHSIG), so even
/// a SIGKILL of rb test leaves no program running on.
int runJobs(const std::vector<Job>& jobs, int parallel,
             const std::function<void(size_t, const JobOutcome&)>& done,
             const std::function<std::string(size_t)>& start = nullptr);

/// True when this build runs under AddressSanitizer, whose shadow memory does not fit under a
/// memory limit: memoryBytes is then ignored.
bool memoryLimitUnsupported();

}  // namespace rb::grade
