#pragma once
// A pseudo-terminal for the robot emulator: rb keeps the master side and a program under test
// opens the slave side as if it were the robot's serial port. Plus a symbolic link with a
// stable name pointing at the slave, removed again when the emulator ends.

#include <string>

namespace rb::drivers {

/// A pseudo-terminal pair; rb holds the master, clients open slavePath().
class Pty {
 public:
  /// Opens a new pseudo-terminal (posix_openpt, grantpt, unlockpt) with a non-blocking master.
  /// Throws RuntimeError when the system has none to give.
  Pty();
  ~Pty();
  Pty(const Pty&) = delete;
  Pty& operator=(const Pty&) = delete;

  /// The master side's descriptor (non-blocking), -1 once closed.
  int master() const { return master_; }
  /// The device a client opens ("/dev/pts/7").
  const std::string& slavePath() const { return slavePath_; }
  /// Closes the master: a client still connected sees a hang-up.
  void close();

 private:
  int master_ = -1;
  std::string slavePath_;
};

/// A symbolic link `link` -> `target` for as long as this object lives. A stale symbolic link
/// of the same name (left by an emulator that was killed) is replaced; any other file there is
/// an error.
class SymlinkGuard {
 public:
  SymlinkGuard(std::string link, const std::string& target);
  ~SymlinkGuard();
  SymlinkGuard(const SymlinkGuard&) = delete;
  SymlinkGuard& operator=(const SymlinkGuard&) = delete;

  /// The link's own path.
  const std::string& path() const { return link_; }

 private:
  std::string link_;
  std::string target_;
};

}  // namespace rb::drivers
