#include "kernel_confine.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#if defined(__linux__)
#include <linux/capability.h>
#include <linux/landlock.h>
#include <sched.h>
#include <seccomp.h>
#include <sys/ioctl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#endif

namespace rb::run {

namespace {

/// Sanitizer builds (the test suite's second run): LeakSanitizer stops the world with a
/// ptrace-ing clone and reads /proc/self/maps, so those stay allowed there. Release builds never
/// allow them.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

}  // namespace

#if defined(__linux__)

namespace {

// Landlock's rights by the ABI that brought them; the build machine's header may be older than
// the kernel rb runs on, so the newer ones are spelled out here.
constexpr uint64_t kFsExecute = 1ull << 0;
constexpr uint64_t kFsWriteFile = 1ull << 1;
constexpr uint64_t kFsReadFile = 1ull << 2;
constexpr uint64_t kFsReadDir = 1ull << 3;
constexpr uint64_t kFsRemoveDir = 1ull << 4;
constexpr uint64_t kFsRemoveFile = 1ull << 5;
constexpr uint64_t kFsMakeDir = 1ull << 7;
constexpr uint64_t kFsMakeReg = 1ull << 8;
constexpr uint64_t kFsMakeSym = 1ull << 12;
constexpr uint64_t kFsRefer = 1ull << 13;     // ABI 2
constexpr uint64_t kFsTruncate = 1ull << 14;  // ABI 3
constexpr uint64_t kFsIoctlDev = 1ull << 15;  // ABI 5
constexpr uint64_t kNetBindTcp = 1ull << 0;     // ABI 4
constexpr uint64_t kNetConnectTcp = 1ull << 1;  // ABI 4
constexpr uint64_t kScopeAbstractUnix = 1ull << 0;  // ABI 6
constexpr uint64_t kScopeSignal = 1ull << 1;        // ABI 6

/// The rights that apply to a file (not a folder).
constexpr uint64_t kFileRights = kFsExecute | kFsWriteFile | kFsReadFile | kFsTruncate | kFsIoctlDev;

/// landlock_ruleset_attr as the newest ABI has it; older kernels are given a shorter prefix.
struct RulesetAttr {
  uint64_t handledFs = 0;
  uint64_t handledNet = 0;
  uint64_t scoped = 0;
};

uint64_t fsRights(int abi) {
  uint64_t all = (kFsMakeSym << 1) - 1;  // ABI 1: execute .. make_sym
  if (abi >= 2) all |= kFsRefer;
  if (abi >= 3) all |= kFsTruncate;
  if (abi >= 5) all |= kFsIoctlDev;
  return all;
}

/// Adds a rule for `path` with `rights` (those a file cannot have left out for a file); a path
/// that does not exist is skipped. False when the kernel refused the rule.
bool addRule(int ruleset, const std::string& path, uint64_t rights, uint64_t handled) {
  int fd = ::open(path.c_str(), O_PATH | O_CLOEXEC);
  if (fd < 0) return true;
  struct stat st{};
  if (::fstat(fd, &st) != 0) {
    ::close(fd);
    return true;
  }
  if (!S_ISDIR(st.st_mode)) rights &= kFileRights;
  rights &= handled;
  bool ok = true;
  if (rights != 0) {
    landlock_path_beneath_attr rule{};
    rule.allowed_access = rights;
    rule.parent_fd = fd;
    ok = ::syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0) == 0;
  }
  ::close(fd);
  return ok;
}

std::string applyLandlock(const KernelRules& rules, int abi) {
  RulesetAttr attr;
  attr.handledFs = fsRights(abi);
  size_t size = sizeof(uint64_t);
  if (abi >= 4) {
    attr.handledNet = kNetBindTcp | kNetConnectTcp;  // no TCP at all
    size = 2 * sizeof(uint64_t);
  }
  if (abi >= 6) {
    // No signals to processes outside the sandbox (rb test, the teacher's shell), no abstract
    // UNIX sockets of other programs.
    attr.scoped = kScopeAbstractUnix | kScopeSignal;
    size = sizeof attr;
  }
  int ruleset = static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, size, 0));
  if (ruleset < 0) return std::string("Landlock refused the rules: ") + std::strerror(errno);
  const uint64_t h = attr.handledFs;
  const uint64_t read = kFsReadFile | kFsReadDir;
  const uint64_t change = read | kFsWriteFile | kFsTruncate | kFsRemoveFile | kFsRemoveDir | kFsMakeReg |
                          kFsMakeDir | kFsMakeSym | kFsRefer;
  const uint64_t output = kFsWriteFile | kFsTruncate | kFsMakeReg | kFsRemoveFile;
  bool ok = true;
  for (const std::string& d : rules.readPaths) ok = addRule(ruleset, d, read, h) && ok;
  for (const std::string& d : rules.writeDirs) ok = addRule(ruleset, d, change, h) && ok;
  for (const std::string& d : rules.outputDirs) ok = addRule(ruleset, d, output, h) && ok;
  for (const std::string& f : rules.outputFiles) ok = addRule(ruleset, f, kFsWriteFile, h) && ok;
  for (const std::string& d : rules.devices) ok = addRule(ruleset, d, kFsReadFile | kFsWriteFile | kFsIoctlDev, h) && ok;
  if (rules.allowSpawn) {
    for (const std::string& p : spawnSystemPaths()) ok = addRule(ruleset, p, read | kFsExecute, h) && ok;
    for (const char* dev : {"/dev/null", "/dev/zero", "/dev/full", "/dev/random", "/dev/urandom"})
      ok = addRule(ruleset, dev, kFsReadFile | kFsWriteFile, h) && ok;
  }
  if (kSanitized) ok = addRule(ruleset, "/proc", read, h) && ok;
  std::string problem;
  if (!ok) problem = std::string("Landlock refused a rule: ") + std::strerror(errno);
  else if (::syscall(SYS_landlock_restrict_self, ruleset, 0) != 0)
    problem = std::string("Landlock could not be put in force: ") + std::strerror(errno);
  ::close(ruleset);
  return problem;
}

/// A rule's condition: argument `arg` masked with `mask` equals `value` (libseccomp's SCMP_A0
/// and SCMP_A1 macros build the same with C99 compound literals, which are not C++).
scmp_arg_cmp masked(unsigned arg, uint64_t mask, uint64_t value) {
  scmp_arg_cmp c{};
  c.arg = arg;
  c.op = SCMP_CMP_MASKED_EQ;
  c.datum_a = mask;
  c.datum_b = value;
  return c;
}

/// The seccomp filter: everything is allowed but what a RobotBASIC program never needs, which
/// fails with EPERM (so a started program sees an ordinary error, not a kill).
std::string applySeccomp(const KernelRules& rules) {
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  if (!ctx) return "seccomp could not be set up";
  int failed = 0;
  auto deny = [&](const char* name, uint32_t action = SCMP_ACT_ERRNO(EPERM)) {
    int nr = seccomp_syscall_resolve_name(name);
    if (nr == __NR_SCMP_ERROR) return;  // not on this architecture
    if (seccomp_rule_add(ctx, action, nr, 0) != 0) ++failed;
  };
  // Networks, other processes' memory, the file system's shape, namespaces, keys, the kernel.
  for (const char* name : {"socket", "ptrace", "process_vm_readv", "process_vm_writev", "pidfd_getfd", "kcmp",
                           "mount", "umount2", "pivot_root", "chroot", "fsopen", "fsconfig", "fsmount", "fspick",
                           "move_mount", "open_tree", "mount_setattr", "unshare", "setns", "keyctl", "add_key",
                           "request_key", "bpf", "perf_event_open", "userfaultfd", "init_module", "finit_module",
                           "delete_module", "kexec_load", "kexec_file_load", "reboot", "swapon", "swapoff", "acct",
                           "quotactl", "settimeofday", "clock_settime", "clock_adjtime", "adjtimex", "sethostname",
                           "setdomainname", "syslog", "vhangup", "iopl", "ioperm", "open_by_handle_at",
                           "name_to_handle_at", "fanotify_init", "io_uring_setup", "io_uring_enter",
                           "io_uring_register", "lookup_dcookie", "uselib"}) {
    std::string_view n(name);
    if (kSanitized && n == "ptrace") continue;  // LeakSanitizer's stop-the-world
    deny(name);
  }
  // clone3's flags are behind a pointer a filter cannot read: it fails as if it did not exist,
  // and the C library falls back to clone, whose flags are checked below.
  deny("clone3", SCMP_ACT_ERRNO(ENOSYS));
  int clone = seccomp_syscall_resolve_name("clone");
  for (uint64_t flag : {uint64_t{CLONE_NEWNS}, uint64_t{CLONE_NEWCGROUP}, uint64_t{CLONE_NEWUTS}, uint64_t{CLONE_NEWIPC},
                        uint64_t{CLONE_NEWUSER}, uint64_t{CLONE_NEWPID}, uint64_t{CLONE_NEWNET}})
    if (seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), clone, 1, masked(0, flag, flag)) != 0) ++failed;
  if (!rules.allowSpawn) {
    // No other program, and no second process: only threads (CLONE_THREAD) may be made.
    deny("execve");
    deny("execveat");
    deny("fork");
    deny("vfork");
    if (!kSanitized &&
        seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), clone, 1,
                         masked(0, uint64_t{CLONE_THREAD}, uint64_t{0})) != 0)
      ++failed;
  }
  // Typing into the terminal rb runs in (TIOCSTI) or the console's keyboard (TIOCLINUX).
  int ioctl = seccomp_syscall_resolve_name("ioctl");
  for (uint64_t request : {uint64_t{TIOCSTI}, uint64_t{TIOCLINUX}})
    if (seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), ioctl, 1, masked(1, 0xFFFFFFFFu, request)) != 0)
      ++failed;
  std::string problem;
  if (failed) problem = "seccomp refused " + std::to_string(failed) + " rule(s)";
  else if (int rc = seccomp_load(ctx); rc != 0)
    problem = std::string("seccomp could not be put in force: ") + std::strerror(-rc);
  seccomp_release(ctx);
  return problem;
}

/// Root's capabilities (rb test as root in CI): none for the program, nor for what it starts.
void dropCapabilities() {
  for (int cap = 0; cap <= 63; ++cap)
    if (::prctl(PR_CAPBSET_READ, cap, 0, 0, 0) == 1) ::prctl(PR_CAPBSET_DROP, cap, 0, 0, 0);
  ::prctl(PR_CAP_AMBIENT, PR_CAP_AMBIENT_CLEAR_ALL, 0, 0, 0);
  __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
  __user_cap_data_struct data[2]{};
  ::syscall(SYS_capset, &header, data);
}

void limit(int resource, uint64_t bytes) {
  struct rlimit r{};
  if (::getrlimit(resource, &r) != 0) return;
  rlim_t want = static_cast<rlim_t>(bytes);
  if (r.rlim_max != RLIM_INFINITY && r.rlim_max < want) want = r.rlim_max;
  r.rlim_cur = want;
  r.rlim_max = want;
  ::setrlimit(resource, &r);
}

}  // namespace

int landlockAbi() {
  long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  return abi > 0 ? static_cast<int>(abi) : 0;
}

std::string kernelConfinementGap() {
  if (landlockAbi() > 0) return "";
  return "this kernel has no Landlock (Linux 5.13 or later with it switched on): programs are confined by "
         "rb's own checks and the seccomp filter only";
}

KernelStatus confineProcess(const KernelRules& rules) {
  KernelStatus status;
  // Needed by both Landlock and seccomp for an unprivileged process, and what makes a set-user-ID
  // program started later run without its privileges.
  ::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0);
  struct rlimit none{0, 0};
  ::setrlimit(RLIMIT_CORE, &none);
  if (rules.dataBytes && !kSanitized) limit(RLIMIT_DATA, rules.dataBytes);
  if (rules.fileBytes) limit(RLIMIT_FSIZE, rules.fileBytes);
  if (rules.dropCapabilities) dropCapabilities();
  status.landlockAbi = landlockAbi();
  std::vector<std::string> problems;
  if (status.landlockAbi == 0) {
    problems.push_back(kernelConfinementGap());
  } else if (std::string why = applyLandlock(rules, status.landlockAbi); !why.empty()) {
    problems.push_back(why);
  } else {
    status.landlock = true;
  }
  if (std::string why = applySeccomp(rules); !why.empty()) problems.push_back(why);
  else status.seccomp = true;
  for (const std::string& p : problems) status.problem += (status.problem.empty() ? "" : "; ") + p;
  return status;
}

std::vector<std::string> spawnSystemPaths() {
  return {"/usr",           "/bin",           "/sbin",         "/lib",           "/lib32",
          "/lib64",         "/libx32",        "/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d",
          "/etc/localtime", "/etc/nsswitch.conf", "/etc/passwd", "/etc/group"};
}

std::vector<std::string> serialDevicePaths() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/dev", ec)) {
    std::string name = entry.path().filename().string();
    for (const char* prefix : {"ttyS", "ttyUSB", "ttyACM", "rfcomm"})
      if (name.rfind(prefix, 0) == 0) out.push_back(entry.path().string());
  }
  return out;
}

#else  // no Landlock or seccomp: rb's own checks are the only line

int landlockAbi() { return 0; }

std::string kernelConfinementGap() {
  return "this system has no Landlock or seccomp: programs are confined by rb's own checks only";
}

KernelStatus confineProcess(const KernelRules&) {
  KernelStatus status;
  status.problem = kernelConfinementGap();
  return status;
}

std::vector<std::string> spawnSystemPaths() { return {}; }

std::vector<std::string> serialDevicePaths() {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/dev", ec))
    if (entry.path().filename().string().rfind("cu.", 0) == 0) out.push_back(entry.path().string());
  return out;
}

#endif

}  // namespace rb::run
