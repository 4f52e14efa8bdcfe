#pragma once
// The seccomp filter's rules, written once (docs/confinement.md, "What the kernel enforces").
// libseccomp turns them into classic BPF at build time (seccomp_gen.cpp writes every variant into
// a source file rb embeds: rb itself never links libseccomp and builds no filter at run time),
// and the tests build them again with libseccomp to check that what rb embeds is that filter,
// byte for byte.

#include <cstdint>
#include <string>
#include <vector>

namespace rb::run::seccomp {

/// The filter for one variant, as the kernel's struct sock_filter array (8 bytes an
/// instruction), built by libseccomp for this processor. What it does:
/// everything is allowed but what a RobotBASIC program never needs, which fails with EPERM (so a
/// started program sees an ordinary error, not a kill): socket, ptrace, process_vm_readv/writev,
/// pidfd_getfd, kcmp, the mount calls, pivot_root, chroot, unshare, setns, the key calls, bpf,
/// perf_event_open, userfaultfd, the module and kexec calls, reboot, swapon/off, acct, quotactl,
/// the clock and host-name setters, syslog, vhangup, iopl/ioperm, the handle calls,
/// fanotify_init, io_uring, lookup_dcookie and uselib; without allowSpawn also execve, execveat,
/// fork and vfork. clone3 fails with ENOSYS (its flags cannot be read); clone fails with EPERM
/// with a new-namespace flag, and without allowSpawn unless CLONE_THREAD; ioctl fails with EPERM
/// for TIOCSTI and TIOCLINUX. Another processor's system calls end the thread.
/// `sanitized`: the sanitizer builds' exceptions (LeakSanitizer's stop-the-world ptrace-es
/// from a clone without CLONE_THREAD), never in a release build.
/// Empty, with `error` set, when libseccomp refused something.
std::vector<uint8_t> filterBytes(bool allowSpawn, bool sanitized, std::string& error);

/// The architecture the filter is for (libseccomp's native one, an AUDIT_ARCH_* number).
uint32_t nativeArch();

}  // namespace rb::run::seccomp
