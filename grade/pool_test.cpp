#include "pool.h"

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

using namespace rb::grade;
namespace fs = std::filesystem;

namespace {

Job shell(const std::string& script, double timeout = 10) {
  Job j;
  j.argv = {"/bin/sh", "-c", script};
  j.timeoutSeconds = timeout;
  return j;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path scratch() {
  static int count = 0;
  fs::path dir = fs::temp_directory_path() / ("rb_pool_test_" + std::to_string(getpid()) + "_" + std::to_string(++count));
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("jobs run in children with their own files and folder", "[grade][pool]") {
  fs::path dir = scratch();
  std::ofstream(dir / "in.txt") << "hello\n";
  Job j = shell("read line; echo \"got $line in $(basename \"$PWD\")\"; echo oops >&2; exit 3");
  j.cwd = dir.string();
  j.stdinPath = (dir / "in.txt").string();
  j.stdoutPath = (dir / "out.txt").string();
  j.stderrPath = (dir / "err.txt").string();
  std::vector<JobOutcome> got(1);
  runJobs({j}, 1, [&](size_t i, const JobOutcome& o) { got[i] = o; });
  CHECK(got[0].kind == JobOutcome::Exited);
  CHECK(got[0].code == 3);
  CHECK(slurp(j.stdoutPath) == "got hello in " + dir.filename().string() + "\n");
  CHECK(slurp(j.stderrPath) == "oops\n");
  CHECK(describe(got[0], j) == "exit 3");
  fs::remove_all(dir);
}

TEST_CASE("a crash, a hang and a missing program fail only their own job", "[grade][pool]") {
  std::vector<Job> jobs = {shell("exit 0"), shell("kill -SEGV $$"), shell("sleep 30", 0.3),
                           Job{{"/no/such/program"}, "", "", "", "", 5, 0, 0, {}}, shell("exit 7")};
  std::vector<JobOutcome> got(jobs.size());
  std::vector<size_t> order;
  auto start = std::chrono::steady_clock::now();
  runJobs(jobs, 2, [&](size_t i, const JobOutcome& o) {
    got[i] = o;
    order.push_back(i);
  });
  double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(order.size() == jobs.size());
  CHECK(got[0].kind == JobOutcome::Exited);
  CHECK(got[0].code == 0);
  CHECK(got[1].kind == JobOutcome::Signalled);
  CHECK(got[1].signal == SIGSEGV);
  CHECK(describe(got[1], jobs[1]) == "killed by signal 11 (SIGSEGV)");
  CHECK(got[2].kind == JobOutcome::TimedOut);
  CHECK(describe(got[2], jobs[2]) == "killed after 0.3 s (the time limit)");
  CHECK(got[3].kind == JobOutcome::NotStarted);
  CHECK(got[3].error == "/no/such/program: No such file or directory");
  CHECK(got[4].code == 7);
  CHECK(took < 10);  // the sleeping job was killed, not waited for
}

TEST_CASE("a job's time for reports comes after its time limit, and a kill names both", "[grade][pool]") {
  // The same half-second job: killed at its 0.2 s limit alone, finished with 2 s more for
  // reports; one that never ends is killed at the sum.
  Job alone = shell("sleep 0.5; exit 4", 0.2), more = alone, never = shell("sleep 30", 0.2);
  more.reportSeconds = 2;
  never.reportSeconds = 0.2;
  std::vector<JobOutcome> got(3);
  runJobs({alone, more, never}, 3, [&](size_t i, const JobOutcome& o) { got[i] = o; });
  CHECK(got[0].kind == JobOutcome::TimedOut);
  CHECK(got[1].kind == JobOutcome::Exited);
  CHECK(got[1].code == 4);
  CHECK(got[2].kind == JobOutcome::TimedOut);
  CHECK(describe(got[2], never) == "killed after 0.4 s (the time limit)");
  CHECK(got[2].seconds >= 0.4);
}

TEST_CASE("at most N jobs run at once", "[grade][pool]") {
  fs::path dir = scratch();
  // Each job marks itself running with a file of its own, counts the marks, and removes its
  // mark before it ends.
  fs::create_directories(dir / "running");
  std::string running = (dir / "running").string(), seen = (dir / "seen").string();
  std::string script = "touch '" + running + "'/$$; ls '" + running + "' | wc -l >> '" + seen +
                       "'; sleep 0.2; rm '" + running + "'/$$";
  std::vector<Job> jobs(6, shell(script));
  runJobs(jobs, 2, [](size_t, const JobOutcome&) {});
  std::istringstream counts(slurp(seen));
  int n, most = 0, count = 0;
  while (counts >> n) {
    most = std::max(most, n);
    ++count;
  }
  CHECK(count == 6);
  CHECK(most <= 2);
  fs::remove_all(dir);
}

TEST_CASE("a child that writes too much is stopped by the file size limit", "[grade][pool]") {
  fs::path dir = scratch();
  Job j = shell("head -c 5000000 /dev/zero");
  j.stdoutPath = (dir / "out").string();
  j.fileBytes = 1 << 20;
  JobOutcome got;
  runJobs({j}, 1, [&](size_t, const JobOutcome& o) { got = o; });
  // head dies of SIGXFSZ; the shell that ran it reports 128 + the signal.
  bool stopped = (got.kind == JobOutcome::Signalled && got.signal == SIGXFSZ) ||
                 (got.kind == JobOutcome::Exited && got.code == 128 + SIGXFSZ);
  CHECK(stopped);
  CHECK(fs::file_size(j.stdoutPath) <= (1u << 20));
  fs::remove_all(dir);
}

TEST_CASE("a child that eats memory runs into its memory limit", "[grade][pool]") {
  if (memoryLimitUnsupported()) SUCCEED("AddressSanitizer build: no memory limit");
  else if (access("/usr/bin/python3", X_OK) != 0) SUCCEED("python3 is not installed");
  else {
    Job j;
    j.argv = {"/usr/bin/python3", "-c", "x = bytearray(1 << 30)"};
    j.memoryBytes = 256ull << 20;
    fs::path dir = scratch();
    j.stderrPath = (dir / "err").string();
    JobOutcome got;
    runJobs({j}, 1, [&](size_t, const JobOutcome& o) { got = o; });
    CHECK(got.kind == JobOutcome::Exited);
    CHECK(got.code != 0);
    CHECK(slurp(j.stderrPath).find("MemoryError") != std::string::npos);
    fs::remove_all(dir);
  }
}

TEST_CASE("what a job starts in the background ends with it, finished or killed", "[grade][pool]") {
  fs::path dir = scratch();
  // One job exits at once, leaving a sleeper behind; the other is killed at its time limit with
  // its sleeper. Neither sleeper survives runJobs.
  Job left = shell("sleep 60 & echo $! > left.pid; exit 0");
  left.cwd = dir.string();
  Job hung = shell("sleep 60 & echo $! > hung.pid; sleep 60", 0.3);
  hung.cwd = dir.string();
  std::vector<JobOutcome> got(2);
  runJobs({left, hung}, 2, [&](size_t i, const JobOutcome& o) { got[i] = o; });
  CHECK(got[0].kind == JobOutcome::Exited);
  CHECK(got[1].kind == JobOutcome::TimedOut);
  for (const char* file : {"left.pid", "hung.pid"}) {
    INFO(file);
    pid_t sleeper = std::stoi(slurp((dir / file).string()));
    // Killed; reaped by init (it was re-parented), so at most a zombie for a moment.
    bool gone = false;
    for (int i = 0; i < 100 && !gone; ++i) {
      std::string state = slurp("/proc/" + std::to_string(sleeper) + "/stat");
      gone = state.empty() || state.find(") Z") != std::string::npos;
      if (!gone) usleep(10000);
    }
    CHECK(gone);
  }
  fs::remove_all(dir);
}
