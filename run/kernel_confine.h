#pragma once
// The kernel's part of what a program may touch (docs/confinement.md, "What the kernel
// enforces"): Landlock decides which files the process may open, create, rename or execute; a
// seccomp filter refuses the system calls no RobotBASIC program needs (sockets, ptrace, mount,
// namespaces, keyrings, bpf, modules, and starting programs unless --allow-spawn); rlimits bound
// memory, file size and core files. Applied once, before a program runs, to the whole process
// and to everything it starts afterwards; it cannot be undone, which is the point.
//
// rb's own checks (sandbox.h) stay in force on top: they are right on their own, and they are
// all there is where the kernel has no Landlock (older kernels, macOS).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rb::run {

/// What a confined process may reach. Paths that do not exist are left out.
struct KernelRules {
  /// Folders it may read and list, with everything below them, and files it may read.
  std::vector<std::string> readPaths;
  /// Folders it may also change: create, write, rename and remove files and folders below them
  /// (the program's folder tree, or rb test's scratch folder).
  std::vector<std::string> writeDirs;
  /// Folders rb writes its own results into after the run (rb render -o, rb trace --out): files
  /// may be created and replaced there, nothing read.
  std::vector<std::string> outputDirs;
  /// Files that are there and are not regular files (a FIFO, /dev/stdout's terminal) which rb
  /// writes its results to as they are.
  std::vector<std::string> outputFiles;
  /// Device files it may open for reading and writing, with their ioctls (serial ports).
  std::vector<std::string> devices;
  /// Other programs may be started (Spawn, granted by the person running rb): execve is allowed
  /// and the system folders a program needs become readable and executable.
  bool allowSpawn = false;
  /// RLIMIT_DATA in bytes (0: unchanged): the kernel's backstop under --max-memory.
  uint64_t dataBytes = 0;
  /// RLIMIT_FSIZE in bytes (0: unchanged): the largest file the process may write.
  uint64_t fileBytes = 0;
  /// Give up every capability (rb test's programs: a class graded as root in CI runs them
  /// without root's powers, and nothing they start can gain them back).
  bool dropCapabilities = false;
};

/// One instruction of a classic BPF program (Linux's struct sock_filter).
struct BpfInstruction {
  uint16_t code;
  uint8_t jt, jf;
  uint32_t k;
};

/// The seccomp filter confineProcess puts in force, as libseccomp built it at build time from
/// the rules in seccomp/seccomp_rules.cpp (what it refuses is said there), for each variant:
/// with or without KernelRules::allowSpawn, and with or without the sanitizer builds'
/// exceptions (a release build uses only the variants without them). Linux only.
std::span<const BpfInstruction> embeddedSeccompProgram(bool allowSpawn, bool sanitized);
/// The processor those filters are for (an AUDIT_ARCH_* number).
uint32_t embeddedSeccompArch();

/// What was put in force.
struct KernelStatus {
  int landlockAbi = 0;    ///< the kernel's Landlock ABI (0: none)
  bool landlock = false;  ///< the file rules are in force
  bool seccomp = false;   ///< the system-call filter is in force
  /// Why a layer is missing ("this kernel has no Landlock (...)"), or "" when both are in force.
  std::string problem;
  bool complete() const { return landlock && seccomp; }
};

/// The Landlock ABI version this kernel offers, 0 when it has none (or it is switched off).
int landlockAbi();

/// One sentence for reports when the kernel cannot confine programs, or "" when it can: rb's
/// own checks are then the only line (docs/confinement.md).
std::string kernelConfinementGap();

/// Confines this process for good: no new privileges, no capabilities, Landlock with `rules`,
/// the seccomp filter, the rlimits. Never throws; what could not be done is in the result.
KernelStatus confineProcess(const KernelRules& rules);

/// The folders a started program reads and executes from (/usr, /bin, /lib...), and the few
/// files of /etc it reads (the dynamic linker's cache, the time zone, user names): what
/// KernelRules::allowSpawn makes readable.
std::vector<std::string> spawnSystemPaths();

/// The device files a serial port number or --port can name on this machine (/dev/ttyS*,
/// /dev/ttyUSB*, /dev/ttyACM*, /dev/rfcomm*), for KernelRules::devices.
std::vector<std::string> serialDevicePaths();

}  // namespace rb::run
