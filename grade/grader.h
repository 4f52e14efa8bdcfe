#pragma once
// `rb test`'s engine: finds the programs, runs each in a child process (rb itself, through the
// hidden `rb test-job` command) several at a time, and grades the runs against the programs'
// comments or an assignment file.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "checks.h"

namespace rb::grade {

struct GradeOptions {
  std::vector<std::string> paths;         ///< files and folders (searched for *.bas)
  std::string assignmentPath;             ///< "" : expectations come from the comments
  int jobs = 0;                           ///< programs at once (0: one per core)
  int shard = 1, shards = 1;              ///< grade only the programs of shard K of N
  uint64_t seed = 1;                      ///< comment mode: the seed when // args gives none
  std::optional<uint64_t> maxSteps;       ///< overrides the assignment's and the comments'
  std::optional<double> timeout;          ///< seconds: overrides the assignment's / // timeout
  std::string picturesDir;                ///< "" : no pictures
  /// How to start a child that runs one program: rb itself and the hidden subcommand.
  std::vector<std::string> childCommand;
  /// Called as each program is graded (in the order they finish).
  std::function<void(size_t done, size_t total)> progress;
};

struct ProgramResult {
  std::string program;             ///< the path as found
  std::string verdict;             ///< "pass", "fail", "skip" or "error" (rb could not grade it)
  std::string reason;              ///< the first failed check's message, or why it was skipped
  std::vector<CheckResult> checks;
  uint64_t steps = 0;              ///< of the first run
  double seconds = 0;              ///< wall time of all its runs
  double points = 0, maxPoints = 0;
  std::string output;              ///< the first run's output (for reports), shortened
  std::string errors;              ///< the first run's standard error, shortened
  std::string picture;             ///< the PNG written for it, or ""
};

struct ClassResult {
  std::string title;               ///< the assignment's title, or "rb test"
  std::vector<ProgramResult> programs;
  double seconds = 0;              ///< wall time of the whole grading
  size_t passed = 0, failed = 0, skipped = 0, errors = 0;
  std::string timestamp;           ///< ISO 8601, UTC, when grading started
  // When grading could not happen at all: the message and rb's exit code (64 usage, 66 no
  // input, 74 I/O). 0 otherwise.
  int fatalCode = 0;
  std::string fatal;
};

ClassResult gradeClass(const GradeOptions& options);

/// The programs `paths` name, as rb test finds them: files as given, folders searched
/// recursively for *.bas (any case), sorted, without files whose first line is `// nontest`.
/// Throws std::runtime_error naming a path that does not exist.
std::vector<std::string> findPrograms(const std::vector<std::string>& paths);

/// The programs of shard K of N (1-based): every N-th program starting with the K-th.
std::vector<std::string> shardOf(const std::vector<std::string>& programs, int shard, int shards);

}  // namespace rb::grade
