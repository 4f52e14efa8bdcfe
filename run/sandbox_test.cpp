#include "sandbox.h"

#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "base/runtime_error.h"
#include "kernel_confine.h"

#if defined(__linux__)
#include <linux/audit.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/ioctl.h>

#include <cstdio>
#include <cstring>
#include <string_view>
#include <vector>
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

#if defined(__linux__) && (defined(__x86_64__) || defined(__aarch64__))
namespace {

/// Runs a classic BPF program on a system call (struct seccomp_data: nr, arch, the
/// instruction pointer, six arguments), as the kernel does: what it returns.
uint32_t runBpf(const std::vector<BpfInstruction>& code, uint32_t arch, uint32_t nr, const uint64_t (&args)[6]) {
  unsigned char data[64] = {};
  std::memcpy(data, &nr, 4);
  std::memcpy(data + 4, &arch, 4);
  std::memcpy(data + 16, args, sizeof args);
  uint32_t a = 0, x = 0, mem[16] = {};
  for (size_t pc = 0; pc < code.size(); ++pc) {
    const BpfInstruction& in = code[pc];
    const uint32_t src = (in.code & 0x08) ? x : in.k;  // BPF_X : BPF_K
    switch (in.code & 0x07) {
      case 0x00:  // BPF_LD
        if ((in.code & 0xe0) == 0x20) {  // BPF_ABS, words only
          REQUIRE(in.k + 4 <= sizeof data);
          std::memcpy(&a, data + in.k, 4);
        } else if ((in.code & 0xe0) == 0x00) a = in.k;  // BPF_IMM
        else if ((in.code & 0xe0) == 0x60) a = mem[in.k & 15];  // BPF_MEM
        else FAIL("unexpected load " << in.code);
        break;
      case 0x01:  // BPF_LDX
        x = (in.code & 0xe0) == 0x60 ? mem[in.k & 15] : in.k;
        break;
      case 0x02: mem[in.k & 15] = a; break;  // BPF_ST
      case 0x03: mem[in.k & 15] = x; break;  // BPF_STX
      case 0x04:  // BPF_ALU
        switch (in.code & 0xf0) {
          case 0x00: a += src; break;
          case 0x10: a -= src; break;
          case 0x50: a &= src; break;
          case 0x40: a |= src; break;
          case 0xa0: a ^= src; break;
          case 0x60: a <<= src; break;
          case 0x70: a >>= src; break;
          default: FAIL("unexpected ALU " << in.code);
        }
        break;
      case 0x05: {  // BPF_JMP
        bool taken = false;
        switch (in.code & 0xf0) {
          case 0x00: pc += in.k; continue;  // BPF_JA
          case 0x10: taken = a == src; break;
          case 0x20: taken = a > src; break;
          case 0x30: taken = a >= src; break;
          case 0x40: taken = (a & src) != 0; break;
          default: FAIL("unexpected jump " << in.code);
        }
        pc += taken ? in.jt : in.jf;
        break;
      }
      case 0x06: return (in.code & 0x18) == 0x10 ? a : in.k;  // BPF_RET (A or K)
      case 0x07: if (in.code & 0x80) a = x; else x = a; break;  // BPF_MISC: TXA / TAX
    }
  }
  FAIL("the program ran off its end");
  return 0;
}

/// libseccomp's filter for the same rules, as rb built it before writing its own.
std::vector<BpfInstruction> libseccompProgram(const KernelRules& rules, bool sanitized) {
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  REQUIRE(ctx);
  auto deny = [&](const char* name, uint32_t action = SCMP_ACT_ERRNO(EPERM)) {
    int nr = seccomp_syscall_resolve_name(name);
    if (nr != __NR_SCMP_ERROR) REQUIRE(seccomp_rule_add(ctx, action, nr, 0) == 0);
  };
  for (const char* name : {"socket", "ptrace", "process_vm_readv", "process_vm_writev", "pidfd_getfd", "kcmp",
                           "mount", "umount2", "pivot_root", "chroot", "fsopen", "fsconfig", "fsmount", "fspick",
                           "move_mount", "open_tree", "mount_setattr", "unshare", "setns", "keyctl", "add_key",
                           "request_key", "bpf", "perf_event_open", "userfaultfd", "init_module", "finit_module",
                           "delete_module", "kexec_load", "kexec_file_load", "reboot", "swapon", "swapoff", "acct",
                           "quotactl", "settimeofday", "clock_settime", "clock_adjtime", "adjtimex", "sethostname",
                           "setdomainname", "syslog", "vhangup", "iopl", "ioperm", "open_by_handle_at",
                           "name_to_handle_at", "fanotify_init", "io_uring_setup", "io_uring_enter",
                           "io_uring_register", "lookup_dcookie", "uselib"}) {
    if (sanitized && std::string_view(name) == "ptrace") continue;
    deny(name);
  }
  deny("clone3", SCMP_ACT_ERRNO(ENOSYS));
  int clone = seccomp_syscall_resolve_name("clone");
  for (uint64_t flag : {uint64_t{CLONE_NEWNS}, uint64_t{CLONE_NEWCGROUP}, uint64_t{CLONE_NEWUTS}, uint64_t{CLONE_NEWIPC},
                        uint64_t{CLONE_NEWUSER}, uint64_t{CLONE_NEWPID}, uint64_t{CLONE_NEWNET}})
    REQUIRE(seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), clone, 1, SCMP_A0(SCMP_CMP_MASKED_EQ, flag, flag)) == 0);
  if (!rules.allowSpawn) {
    for (const char* name : {"execve", "execveat", "fork", "vfork"}) deny(name);
    if (!sanitized)
      REQUIRE(seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), clone, 1,
                               SCMP_A0(SCMP_CMP_MASKED_EQ, uint64_t{CLONE_THREAD}, uint64_t{0})) == 0);
  }
  int ioctl = seccomp_syscall_resolve_name("ioctl");
  for (uint64_t request : {uint64_t{TIOCSTI}, uint64_t{TIOCLINUX}})
    REQUIRE(seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), ioctl, 1, SCMP_A1(SCMP_CMP_MASKED_EQ, 0xFFFFFFFFu, request)) == 0);
  FILE* f = std::tmpfile();
  REQUIRE(f);
  REQUIRE(seccomp_export_bpf(ctx, fileno(f)) == 0);
  seccomp_release(ctx);
  std::rewind(f);
  std::vector<BpfInstruction> code;
  BpfInstruction in;
  while (std::fread(&in, sizeof in, 1, f) == 1) code.push_back(in);
  std::fclose(f);
  return code;
}

}  // namespace

TEST_CASE("kernel: rb's seccomp filter decides every system call as libseccomp's did", "[sandbox][kernel]") {
  // As kernel_confine.cpp: the sanitizer builds allow what LeakSanitizer needs.
#if defined(__SANITIZE_ADDRESS__)
  const bool sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  const bool sanitized = true;
#else
  const bool sanitized = false;
#endif
#else
  const bool sanitized = false;
#endif
#if defined(__x86_64__)
  const uint32_t native = AUDIT_ARCH_X86_64;
#else
  const uint32_t native = AUDIT_ARCH_AARCH64;
#endif
  for (bool spawn : {false, true}) {
    KernelRules rules;
    rules.allowSpawn = spawn;
    const std::vector<BpfInstruction> ours = seccompProgram(rules), theirs = libseccompProgram(rules, sanitized);
    REQUIRE(!ours.empty());
    std::vector<uint32_t> numbers;
    for (uint32_t nr = 0; nr < 1024; ++nr) numbers.push_back(nr);
    for (uint32_t nr : {0x40000000u, 0x40000001u, 0x4000003bu, 0x40000200u, 0x7fffffffu, 0xffffffffu})
      numbers.push_back(nr);
    std::vector<uint64_t> firsts = {0, 1, uint64_t{1} << 32, CLONE_THREAD, CLONE_VM | CLONE_FS | CLONE_FILES | CLONE_SIGHAND | CLONE_THREAD,
                                    (uint64_t{1} << 32) | CLONE_THREAD, TIOCSTI, TIOCLINUX, TIOCSTI | (uint64_t{1} << 32), 0x5401};
    for (uint64_t flag : {uint64_t{CLONE_NEWNS}, uint64_t{CLONE_NEWCGROUP}, uint64_t{CLONE_NEWUTS}, uint64_t{CLONE_NEWIPC},
                          uint64_t{CLONE_NEWUSER}, uint64_t{CLONE_NEWPID}, uint64_t{CLONE_NEWNET}}) {
      firsts.push_back(flag);
      firsts.push_back(flag | CLONE_THREAD);
    }
    size_t checked = 0;
    for (uint32_t arch : {native, uint32_t{AUDIT_ARCH_I386}, uint32_t{AUDIT_ARCH_ARM}, 0u})
      for (uint32_t nr : numbers)
        for (uint64_t first : firsts) {
          const uint64_t args[6] = {first, first, 3, 4, 5, 6};
          INFO("spawn " << spawn << ", arch " << std::hex << arch << ", system call " << std::dec << nr << ", arguments "
                        << std::hex << first);
          const uint32_t want = runBpf(theirs, arch, nr, args), got = runBpf(ours, arch, nr, args);
          REQUIRE(got == want);
          ++checked;
        }
    CHECK(checked > 90000);
  }
}
#endif
