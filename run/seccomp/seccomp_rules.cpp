#include "seccomp_rules.h"

#include <sched.h>
#include <seccomp.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string_view>

namespace rb::run::seccomp {

namespace {

/// A rule's condition: argument `arg` masked with `mask` equals `value`.
scmp_arg_cmp masked(unsigned arg, uint64_t mask, uint64_t value) {
  scmp_arg_cmp c{};
  c.arg = arg;
  c.op = SCMP_CMP_MASKED_EQ;
  c.datum_a = mask;
  c.datum_b = value;
  return c;
}

/// Adds the rules to `ctx` (everything allowed by default). The number of rules refused.
int addRules(scmp_filter_ctx ctx, bool allowSpawn, bool sanitized) {
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
    if (sanitized && std::string_view(name) == "ptrace") continue;  // LeakSanitizer's stop-the-world
    deny(name);
  }
  // clone3's flags are behind a pointer a filter cannot read: it fails as if it did not exist,
  // and the C library falls back to clone, whose flags are checked below.
  deny("clone3", SCMP_ACT_ERRNO(ENOSYS));
  const int clone = seccomp_syscall_resolve_name("clone");
  for (uint64_t flag : {uint64_t{CLONE_NEWNS}, uint64_t{CLONE_NEWCGROUP}, uint64_t{CLONE_NEWUTS}, uint64_t{CLONE_NEWIPC},
                        uint64_t{CLONE_NEWUSER}, uint64_t{CLONE_NEWPID}, uint64_t{CLONE_NEWNET}})
    if (seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), clone, 1, masked(0, flag, flag)) != 0) ++failed;
  if (!allowSpawn) {
    // No other program, and no second process: only threads (CLONE_THREAD) may be made.
    deny("execve");
    deny("execveat");
    deny("fork");
    deny("vfork");
    if (!sanitized &&
        seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), clone, 1, masked(0, uint64_t{CLONE_THREAD}, uint64_t{0})) != 0)
      ++failed;
  }
  // Typing into the terminal rb runs in (TIOCSTI) or the console's keyboard (TIOCLINUX).
  const int ioctl = seccomp_syscall_resolve_name("ioctl");
  for (uint64_t request : {uint64_t{TIOCSTI}, uint64_t{TIOCLINUX}})
    if (seccomp_rule_add(ctx, SCMP_ACT_ERRNO(EPERM), ioctl, 1, masked(1, 0xFFFFFFFFu, request)) != 0) ++failed;
  return failed;
}

}  // namespace

std::vector<uint8_t> filterBytes(bool allowSpawn, bool sanitized, std::string& error) {
  std::vector<uint8_t> bytes;
  scmp_filter_ctx ctx = seccomp_init(SCMP_ACT_ALLOW);
  if (!ctx) {
    error = "libseccomp could not start a filter";
    return bytes;
  }
  if (int failed = addRules(ctx, allowSpawn, sanitized); failed != 0) {
    error = "libseccomp refused " + std::to_string(failed) + " rule(s)";
    seccomp_release(ctx);
    return bytes;
  }
  // Debian's libseccomp 2.5 exports to a file descriptor only (seccomp_export_bpf_mem is 2.6's).
  std::FILE* f = std::tmpfile();
  if (!f) {
    error = std::string("no temporary file: ") + std::strerror(errno);
  } else if (int rc = seccomp_export_bpf(ctx, fileno(f)); rc != 0) {
    error = std::string("libseccomp could not export the filter: ") + std::strerror(-rc);
  } else {
    std::rewind(f);
    uint8_t buffer[4096];
    while (size_t n = std::fread(buffer, 1, sizeof buffer, f)) bytes.insert(bytes.end(), buffer, buffer + n);
    if (bytes.empty() || bytes.size() % 8 != 0) {
      error = "libseccomp exported " + std::to_string(bytes.size()) + " bytes, not whole instructions";
      bytes.clear();
    }
  }
  if (f) std::fclose(f);
  seccomp_release(ctx);
  return bytes;
}

uint32_t nativeArch() { return seccomp_arch_native(); }

}  // namespace rb::run::seccomp
