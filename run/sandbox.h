#pragma once
// What a program may reach outside itself (core's SystemAccess): files inside the program's
// folder and the folders given with --allow-files, and other programs only with --allow-spawn.
// Student programs are untrusted; a teacher grading a class runs them as they come.
//
// This is rb's own line of defence, right on its own (the kernel's Landlock rules,
// kernel_confine.h, are the other): a name is resolved by the kernel beneath the folder it
// belongs to (openat2 with RESOLVE_BENEATH), or, where the kernel lacks openat2, one component
// at a time without following a link blindly. A name that cannot be resolved (a link loop, a
// name too long) is refused, never guessed at from its spelling.

#include <string>
#include <vector>

#include "machine/host.h"

namespace rb::run {

class Sandbox : public SystemAccess {
 public:
  /// `home`: the program's folder (where relative names start). `allowed`: more folders files
  /// may be in. `allowSpawn`: Spawn may run commands.
  Sandbox(std::string home, std::vector<std::string> allowed, bool allowSpawn);
  ~Sandbox() override;
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  bool fileExists(std::string_view who, const std::string& path) override;
  void renameFile(std::string_view who, const std::string& from, const std::string& to) override;
  void setDirectory(std::string_view who, const std::string& path) override;
  int64_t spawn(std::string_view who, const std::string& command, bool wait,
                const std::function<void()>& checkpoint) override;

  /// Resolve names one component at a time, as on kernels without openat2 (for tests of that
  /// path; it is chosen by itself where openat2 is missing).
  void resolveByComponents(bool on) { byComponents_ = on; }

 private:
  struct Root {
    std::string path;  ///< absolute, canonical
    int fd = -1;       ///< the folder, opened O_PATH
  };
  /// A name split into the root it lies beneath and its path below that root.
  struct Place {
    size_t root = 0;
    std::string below;  ///< "" for the root itself
  };

  /// Opens `below` beneath root `root` with `flags` (O_PATH...), following links only while they
  /// stay beneath. -1 with errno set: EXDEV when the name leads out.
  int openBeneath(size_t root, const std::string& below, int flags) const;
  int walkBeneath(size_t root, const std::string& below, int flags) const;
  /// Where `path` (relative to the current folder, or absolute) lies: every place it could mean,
  /// the way it is written first, then its canonical form. Throws on an empty name or a NUL.
  std::vector<Place> places(std::string_view who, const std::string& path) const;
  /// Opens `path` (its last component followed) with `flags`; throws RuntimeError when it lies
  /// outside every root or cannot be resolved. -1 with errno (ENOENT, ENOTDIR) when it does not
  /// exist.
  int open(std::string_view who, const std::string& path, int flags, Place* where = nullptr) const;
  [[noreturn]] void refuse(std::string_view who, const std::string& path, int error) const;

  std::vector<Root> roots_;  ///< roots_[0] is the program's folder
  Place current_;            ///< where relative names start (DirSet)
  int currentFd_ = -1;       ///< the current folder, for Spawn's working folder
  bool allowSpawn_;
  bool byComponents_ = false;
};

}  // namespace rb::run
