#pragma once
// What a program may reach outside itself (core's SystemAccess): files inside the program's
// folder and the folders given with --allow-files, and other programs only with --allow-spawn.
// Student programs are untrusted; a teacher grading a class runs them as they come.

#include <string>
#include <vector>

#include "machine/host.h"

namespace rb::cli {

class Sandbox : public SystemAccess {
 public:
  /// `home`: the program's folder (where relative names start). `allowed`: more folders files
  /// may be in. `allowSpawn`: Spawn may run commands.
  Sandbox(std::string home, std::vector<std::string> allowed, bool allowSpawn);

  bool fileExists(std::string_view who, const std::string& path) override;
  void renameFile(std::string_view who, const std::string& from, const std::string& to) override;
  void setDirectory(std::string_view who, const std::string& path) override;
  int64_t spawn(std::string_view who, const std::string& command, bool wait) override;

  /// The absolute, normalized form of a program's file name, or a RuntimeError when it lies
  /// outside every folder the run may reach.
  std::string resolve(std::string_view who, const std::string& path) const;

 private:
  std::vector<std::string> roots_;  ///< normalized folders; roots_[0] is the program's folder
  std::string current_;             ///< where relative names start (DirSet)
  bool allowSpawn_;
};

}  // namespace rb::cli
