#include "sandbox.h"

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "base/runtime_error.h"
#include "kernel_confine.h"

#if defined(__linux__)
#include <sched.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/syscall.h>

#include <cstring>
#include <span>
#include <vector>

#include "seccomp_rules.h"
#endif

using namespace rb;
using namespace rb::run;
namespace fs = std::filesystem;

namespace {
struct TempTree {
  fs::path root;
  TempTree() {
    root = fs::temp_directory_path() / ("rb_sandbox_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "class" / "sub");
    fs::create_directories(root / "other");
    fs::create_directories(root / "teacher");
    std::ofstream(root / "class" / "a.txt") << "a";
    std::ofstream(root / "class" / "payload.txt") << "payload";
    std::ofstream(root / "other" / "b.txt") << "b";
    std::ofstream(root / "teacher" / ".bashrc") << "teacher's";
    std::ofstream(root / "teacher" / "secret.txt") << "secret";
    fs::create_directory_symlink(root / "other", root / "class" / "link");
    fs::create_directory_symlink("../teacher", root / "class" / "home");
    fs::create_symlink("loop", root / "class" / "loop");
    fs::create_symlink("sub/..", root / "class" / "here");
  }
  ~TempTree() { fs::remove_all(root); }
  std::string read(const fs::path& p) const {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
};

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}
}  // namespace

// Every case runs twice: names resolved by the kernel (openat2 RESOLVE_BENEATH) and one
// component at a time, as on a kernel without openat2.
TEST_CASE("sandbox: files inside the program's folder only", "[sandbox]") {
  bool byComponents = GENERATE(false, true);
  TempTree t;
  Sandbox box((t.root / "class").string(), {}, false);
  box.resolveByComponents(byComponents);
  CHECK(box.fileExists("FileExists", "a.txt"));
  CHECK_FALSE(box.fileExists("FileExists", "sub/none.txt"));
  CHECK_FALSE(box.fileExists("FileExists", "sub"));  // a folder is not a file
  CHECK(box.fileExists("FileExists", "here/a.txt"));  // a link that stays inside
  CHECK_THROWS_AS(box.fileExists("FileExists", "../other/b.txt"), RuntimeError);
  CHECK_THROWS_AS(box.fileExists("FileExists", (t.root / "other" / "b.txt").string()), RuntimeError);
  // A symbolic link cannot lead out either.
  CHECK_THROWS_AS(box.fileExists("FileExists", "link/b.txt"), RuntimeError);
  CHECK_THROWS_AS(box.setDirectory("DirSet", ".."), RuntimeError);
  box.setDirectory("DirSet", "sub");
  CHECK(box.fileExists("FileExists", "../a.txt"));
  CHECK_THROWS_AS(box.fileExists("FileExists", "../../other/b.txt"), RuntimeError);
  CHECK_THROWS_AS(box.spawn("Spawn", "true", true, nullptr), RuntimeError);
}

TEST_CASE("sandbox: a name that cannot be resolved is refused, never guessed from its spelling",
          "[sandbox]") {
  bool byComponents = GENERATE(false, true);
  TempTree t;
  Sandbox box((t.root / "class").string(), {}, false);
  box.resolveByComponents(byComponents);
  // A link out, behind a name too long to canonicalise: the lexical form stays inside, the
  // kernel would follow the link.
  std::string longName = "home/" + repeat("x/../", 1100) + ".bashrc";
  CHECK_THROWS_WITH(box.renameFile("FileRename", "payload.txt", longName), Catch::Contains("too long"));
  // A loop of links in front of "..": the lexical form is inside, the link leads out.
  CHECK_THROWS_WITH(box.renameFile("FileRename", "loop/../home/secret.txt", "stolen.txt"),
                    Catch::Contains("too many symbolic links"));
  CHECK_THROWS_WITH(box.renameFile("FileRename", "payload.txt", "home/.bashrc"), Catch::Contains("outside"));
  CHECK(t.read(t.root / "teacher" / ".bashrc") == "teacher's");
  CHECK(fs::exists(t.root / "teacher" / "secret.txt"));
  CHECK_FALSE(fs::exists(t.root / "class" / "stolen.txt"));
  CHECK_THROWS_WITH(box.fileExists("FileExists", std::string("a\0b", 3)), Catch::Contains("NUL"));
  CHECK_THROWS_WITH(box.renameFile("FileRename", "a.txt", ".."), Catch::Contains("not a file name"));
  // Inside, it works.
  box.renameFile("FileRename", "payload.txt", "sub/moved.txt");
  CHECK(fs::exists(t.root / "class" / "sub" / "moved.txt"));
}

TEST_CASE("sandbox: --allow-files and --allow-spawn open more", "[sandbox]") {
  bool byComponents = GENERATE(false, true);
  TempTree t;
  Sandbox box((t.root / "class").string(), {(t.root / "other").string()}, true);
  box.resolveByComponents(byComponents);
  CHECK(box.fileExists("FileExists", "../other/b.txt"));
  CHECK(box.fileExists("FileExists", "link/b.txt"));
  box.renameFile("FileRename", "../other/b.txt", "../other/c.txt");
  CHECK(fs::exists(t.root / "other" / "c.txt"));
  CHECK(box.spawn("Spawn", "exit 7", true, nullptr) == 7);
  CHECK(box.spawn("Spawn", "true", false, nullptr) == 1);
  ::usleep(200000);  // let it end before its folder goes
  CHECK_THROWS_AS(box.fileExists("FileExists", "home/secret.txt"), RuntimeError);
}

TEST_CASE("sandbox: a command waited for ends when the run's limit does", "[sandbox]") {
  TempTree t;
  Sandbox box((t.root / "class").string(), {}, true);
  int calls = 0;
  auto checkpoint = [&calls] {
    if (++calls == 3) throw RuntimeError("the time limit");
  };
  CHECK_THROWS_WITH(box.spawn("Spawn", "exec sleep 30", true, checkpoint), "the time limit");
  CHECK(calls == 3);
}

namespace {
/// Runs `body` in a child process (the kernel's rules cannot be undone) and returns its exit
/// status.
template <class F>
int inChild(F body) {
  pid_t pid = ::fork();
  if (pid == 0) ::_exit(body());
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}
}  // namespace

TEST_CASE("kernel: a confined process reaches only what its rules name", "[sandbox][kernel]") {
  if (landlockAbi() == 0) {
    SUCCEED("this kernel has no Landlock");
    return;
  }
  TempTree t;
  int status = inChild([&] {
    KernelRules rules;
    rules.writeDirs = {(t.root / "class").string()};
    rules.readPaths = {(t.root / "other").string()};
    KernelStatus s = confineProcess(rules);
    if (!s.complete()) return 10;
    if (!std::ifstream(t.root / "class" / "a.txt")) return 11;                      // its folder
    if (!std::ofstream(t.root / "class" / "new.txt")) return 12;                    // it may write
    if (!std::ifstream(t.root / "other" / "b.txt")) return 13;                      // read only
    if (std::ofstream(t.root / "other" / "new.txt")) return 14;
    if (std::ifstream(t.root / "teacher" / "secret.txt")) return 15;                // nothing else
    if (std::ifstream(t.root / "class" / "home" / "secret.txt")) return 16;         // not by a link
#if !defined(__SANITIZE_ADDRESS__)
    // No new process (sanitizer builds allow it: LeakSanitizer's stop-the-world needs one).
    if (::fork() == 0) ::_exit(0);
    else if (errno != EPERM) return 17;
#endif
    return 0;
  });
  CHECK(status == 0);
}

#if defined(__linux__)
TEST_CASE("kernel: the seccomp filter refuses sockets, other programs and namespaces", "[sandbox][kernel]") {
  for (bool spawn : {false, true}) {
    INFO("allowSpawn " << spawn);
    int status = inChild([&] {
      KernelRules rules;
      rules.allowSpawn = spawn;
      if (!confineProcess(rules).seccomp) return 10;
      if (::socket(AF_INET, SOCK_STREAM, 0) >= 0 || errno != EPERM) return 11;
      if (::socket(AF_UNIX, SOCK_STREAM, 0) >= 0 || errno != EPERM) return 12;
      // A new user namespace, asked of clone itself (a child made by mistake leaves at once).
      long pid = ::syscall(SYS_clone, CLONE_NEWUSER | SIGCHLD, 0, 0, 0, 0);
      if (pid == 0) ::_exit(0);
      if (pid > 0 || errno != EPERM) return 13;
#ifdef SYS_clone3
      if (::syscall(SYS_clone3, nullptr, 0) != -1 || errno != ENOSYS) return 14;
#endif
      char c = 'x';
      if (::ioctl(0, TIOCSTI, &c) == 0 || errno != EPERM) return 15;
      char* argv[] = {const_cast<char*>("/bin/false"), nullptr};
      if (!spawn) {
        ::execv("/bin/false", argv);
        if (errno != EPERM) return 16;
      } else {
        // Starting a process is allowed (a program started by Spawn).
        pid_t child = ::fork();
        if (child == 0) ::_exit(7);
        if (child < 0) return 17;
        int st = 0;
        ::waitpid(child, &st, 0);
        if (!WIFEXITED(st) || WEXITSTATUS(st) != 7) return 18;
      }
      return 0;
    });
    CHECK(status == 0);
  }
}

TEST_CASE("kernel: the seccomp filters rb embeds are those libseccomp builds from the rules", "[sandbox][kernel]") {
  // Every variant, whichever this build uses: libseccomp builds each again here, from the same
  // rules (seccomp/seccomp_rules.cpp) as the build-time tool, and the bytes must be the same.
  CHECK(embeddedSeccompArch() == seccomp::nativeArch());
  for (bool sanitized : {false, true})
    for (bool spawn : {false, true}) {
      INFO("allowSpawn " << spawn << ", sanitized " << sanitized);
      std::string error;
      const std::vector<uint8_t> built = seccomp::filterBytes(spawn, sanitized, error);
      REQUIRE(error.empty());
      REQUIRE(!built.empty());
      const std::span<const BpfInstruction> embedded = embeddedSeccompProgram(spawn, sanitized);
      REQUIRE(embedded.size_bytes() == built.size());
      CHECK(std::memcmp(embedded.data(), built.data(), built.size()) == 0);
    }
  // The variants differ where the rules do.
  const auto bytes = [](bool spawn, bool sanitized) {
    const std::span<const BpfInstruction> p = embeddedSeccompProgram(spawn, sanitized);
    const auto* first = reinterpret_cast<const unsigned char*>(p.data());
    return std::vector<unsigned char>(first, first + p.size_bytes());
  };
  CHECK(bytes(false, false) != bytes(true, false));
  CHECK(bytes(false, false) != bytes(false, true));
}
#endif
