#include "pool.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>

namespace rb::grade {

namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  size_t index;
  Clock::time_point start;
  Clock::time_point deadline;
  bool killed = false;
};

/// What the child needs, prepared before fork: after fork only async-signal-safe calls happen.
struct Prepared {
  std::vector<std::string> strings, envStrings;
  std::vector<char*> argv, env;
};

int openOr(const std::string& path, int flags, const char* fallback) {
  return open(path.empty() ? fallback : path.c_str(), flags | O_CLOEXEC, 0644);
}

void limit(int resource, rlim_t soft, rlim_t hard) {
  struct rlimit r{soft, hard};
  setrlimit(resource, &r);
}

/// In the child: redirects, limits, executes. Reports errno on `report` when exec fails.
[[noreturn]] void child(const Job& job, char* const* argv, char* const* env, const sigset_t& mask, int report,
                        pid_t parent) {
  // A process group of its own: what the program starts (Spawn, with --allow-spawn) is in it,
  // and ends with it.
  setpgid(0, 0);
  // Killed when rb test ends, however it ends (even by SIGKILL, which no handler sees); if it
  // ended before this line, at once.
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) _exit(127);
  sigprocmask(SIG_SETMASK, &mask, nullptr);
  int in = openOr(job.stdinPath, O_RDONLY, "/dev/null");
  int out = openOr(job.stdoutPath, O_WRONLY | O_CREAT | O_TRUNC, "/dev/null");
  int err = openOr(job.stderrPath, O_WRONLY | O_CREAT | O_TRUNC, "/dev/null");
  int e = 0;
  if (in < 0 || out < 0 || err < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0) e = errno;
  if (!e && !job.cwd.empty() && chdir(job.cwd.c_str()) != 0) e = errno;
  if (!e) {
    if (job.memoryBytes && !memoryLimitUnsupported()) limit(RLIMIT_AS, job.memoryBytes, job.memoryBytes);
    if (job.fileBytes) limit(RLIMIT_FSIZE, job.fileBytes, job.fileBytes);
    if (job.timeoutSeconds > 0) {
      rlim_t cpu = static_cast<rlim_t>(std::ceil(job.timeoutSeconds + std::max(0.0, job.reportSeconds))) + 1;
      limit(RLIMIT_CPU, cpu, cpu + 1);
    }
    limit(RLIMIT_CORE, 0, 0);
    if (env) execve(argv[0], argv, env);
    else execv(argv[0], argv);
    e = errno;
  }
  ssize_t ignored = write(report, &e, sizeof e);
  (void)ignored;
  _exit(127);
}

}  // namespace

double wallLimit(const Job& job) { return job.timeoutSeconds + std::max(0.0, job.reportSeconds); }

bool memoryLimitUnsupported() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#else
  return false;
#endif
#else
  return false;
#endif
}

std::string describe(const JobOutcome& o, const Job& job) {
  char buf[160];
  switch (o.kind) {
    case JobOutcome::Exited:
      return "exit " + std::to_string(o.code);
    case JobOutcome::Signalled: {
      const char* name = sigabbrev_np(o.signal);
      std::string sig = "signal " + std::to_string(o.signal) + (name ? std::string(" (SIG") + name + ")" : "");
      if (o.signal == SIGXCPU) return "killed after using its CPU time limit (" + sig + ")";
      if (o.signal == SIGXFSZ) {
        std::snprintf(buf, sizeof buf, "killed for writing more than %.0f MB (%s)",
                      static_cast<double>(job.fileBytes) / (1 << 20), sig.c_str());
        return buf;
      }
      return "killed by " + sig;
    }
    case JobOutcome::TimedOut:
      std::snprintf(buf, sizeof buf, "killed after %g s (the time limit)", wallLimit(job));
      return buf;
    case JobOutcome::NotStarted:
      return "could not start: " + o.error;
  }
  return "";
}

int runJobs(const std::vector<Job>& jobs, int parallel,
             const std::function<void(size_t, const JobOutcome&)>& done,
             const std::function<std::string(size_t)>& start) {
  if (parallel < 1) parallel = 1;
  // SIGCHLD wakes the loop. The signals that end rb (Ctrl-C, a closed terminal, kill) are taken
  // here too while jobs run: the children, each in a process group of its own, are ended with
  // their groups first, then rb ends by the same signal.
  sigset_t chld, old;
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaddset(&chld, s);
  sigprocmask(SIG_BLOCK, &chld, &old);

  std::map<pid_t, Running> running;
  size_t next = 0;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && running.size() < static_cast<size_t>(parallel)) {
      size_t index = next++;
      const Job& job = jobs[index];
      JobOutcome outcome;
      if (job.argv.empty()) {
        outcome.error = "no command";
        done(index, outcome);
        continue;
      }
      if (start) {
        if (std::string why = start(index); !why.empty()) {
          outcome.error = why;
          done(index, outcome);
          continue;
        }
      }
      Prepared p;
      p.strings = job.argv;
      for (std::string& s : p.strings) p.argv.push_back(s.data());
      p.argv.push_back(nullptr);
      p.envStrings = job.env;
      for (std::string& s : p.envStrings) p.env.push_back(s.data());
      p.env.push_back(nullptr);
      int report[2];
      if (pipe2(report, O_CLOEXEC) != 0) {
        outcome.error = std::strerror(errno);
        done(index, outcome);
        continue;
      }
      Clock::time_point started = Clock::now();
      pid_t parent = getpid();
      pid_t pid = fork();
      if (pid == 0) child(job, p.argv.data(), job.env.empty() ? nullptr : p.env.data(), old, report[1], parent);
      if (pid > 0) setpgid(pid, pid);  // also here, so that a kill never comes before it
      close(report[1]);
      if (pid < 0) {
        outcome.error = std::string("fork: ") + std::strerror(errno);
        close(report[0]);
        done(index, outcome);
        continue;
      }
      int e = 0;
      ssize_t got;
      do got = read(report[0], &e, sizeof e);
      while (got < 0 && errno == EINTR);
      close(report[0]);
      if (got == static_cast<ssize_t>(sizeof e)) {
        int status;
        waitpid(pid, &status, 0);
        outcome.error = job.argv[0] + ": " + std::strerror(e);
        done(index, outcome);
        continue;
      }
      auto limit = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
          job.timeoutSeconds > 0 ? wallLimit(job) : 1e9));
      running.emplace(pid, Running{index, started, started + limit});
    }
    if (running.empty()) continue;

    // Wait for a child to end or for the nearest deadline.
    Clock::time_point nearest = Clock::time_point::max();
    for (const auto& [pid, r] : running)
      if (!r.killed) nearest = std::min(nearest, r.deadline);
    double wait = std::chrono::duration<double>(nearest - Clock::now()).count();
    wait = std::clamp(wait, 0.0, 1.0);
    struct timespec ts;
    ts.tv_sec = static_cast<time_t>(wait);
    ts.tv_nsec = static_cast<long>((wait - static_cast<double>(ts.tv_sec)) * 1e9);
    int sig = sigtimedwait(&chld, nullptr, &ts);
    if (sig > 0 && sig != SIGCHLD) {
      for (const auto& [pid, r] : running) kill(-pid, SIGKILL);
      for (const auto& [pid, r] : running) waitpid(pid, nullptr, 0);
      sigprocmask(SIG_SETMASK, &old, nullptr);
      return sig;
    }

    Clock::time_point now = Clock::now();
    for (auto it = running.begin(); it != running.end();) {
      // Looked at without reaping: while the child is a zombie its process group cannot be
      // reused, so killing the group afterwards reaches only what the program left running.
      siginfo_t info{};
      int seen = waitid(P_PID, static_cast<id_t>(it->first), &info, WEXITED | WNOHANG | WNOWAIT);
      if (seen == 0 && info.si_pid == 0) {
        if (!it->second.killed && now >= it->second.deadline) {
          kill(-it->first, SIGKILL);
          it->second.killed = true;
        }
        ++it;
        continue;
      }
      kill(-it->first, SIGKILL);
      int status = 0;
      pid_t got = waitpid(it->first, &status, 0);
      JobOutcome outcome;
      outcome.seconds = std::chrono::duration<double>(now - it->second.start).count();
      if (got < 0) {
        outcome.kind = JobOutcome::NotStarted;
        outcome.error = std::string("waitpid: ") + std::strerror(errno);
      } else if (it->second.killed) {
        outcome.kind = JobOutcome::TimedOut;
      } else if (WIFEXITED(status)) {
        outcome.kind = JobOutcome::Exited;
        outcome.code = WEXITSTATUS(status);
      } else {
        outcome.kind = JobOutcome::Signalled;
        outcome.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      }
      size_t index = it->second.index;
      it = running.erase(it);
      done(index, outcome);
    }
  }
  sigprocmask(SIG_SETMASK, &old, nullptr);
  return 0;
}

}  // namespace rb::grade
