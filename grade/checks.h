#pragma once
// Grading one program: its runs (one per seed) against the expectations in its comments or
// against an assignment's checks. Every failed check says which and by how much.

#include <optional>
#include <string>
#include <vector>

#include "assignment.h"
#include "png_writer.h"
#include "pool.h"
#include "record.h"
#include "spec.h"

namespace rb::grade {

/// Everything the grading process knows about one run of a program.
struct RunOutcome {
  uint64_t seed = 0;
  JobOutcome process;
  std::string processText;       ///< describe(process, job)
  std::string output;            ///< standard output (at most kOutputCap bytes)
  bool outputCut = false;        ///< there was more
  std::string errors;            ///< standard error (at most kOutputCap bytes)
  std::optional<record::RunRecord> record;
  std::string recordError;       ///< why there is no record
  std::optional<record::Screen> screen;
  std::string replayFile;        ///< the replay the run wrote (a temporary file), or ""
};

/// The most output of a run rb test keeps (and compares).
constexpr size_t kOutputCap = 1 << 20;

struct CheckResult {
  std::string name;     ///< as the report shows it ("trail", or the name the assignment gave)
  bool passed = false;
  std::string message;  ///< what was found, and by how much it missed
  double points = 1;    ///< what it is worth
  double earned = 0;    ///< what it earned: its points when passed (a tier's), 0 when not counted
  bool checked = true;  ///< false: not checked (it needs another check that failed)
  std::string note;     ///< why a passed check earns nothing ("not counted: ...")
  std::string hint;     ///< the teacher's hint, shown under a failure
  bool hidden = false;  ///< a student's report shows only that a hidden check failed
  bool required = false;
  /// More lines under the message: what a teacher's post program printed, or every diagnostic
  /// a check kind counted beyond the first.
  std::vector<std::string> feedback;
  /// Where on the screen the check failed (the robot entered a region, touched a colour,
  /// crashed, ended outside, missed a waypoint), in the first seed's run; for pictures.
  std::optional<record::P2> at;
};

/// How each limit of a run is named in messages, as whoever set it wrote it
/// ("max-steps = 100000 in square.toml", "// timeout: 2", "rb test --timeout 5").
struct LimitNames {
  std::string steps = "the step limit";
  std::string time = "the time limit";
};

/// The expectations of a program's comments (golden-test semantics: testdata/README.md).
std::vector<CheckResult> checkComments(const CommentSpec& spec, const RunOutcome& run, const LimitNames& limits);

/// What the assignment's checks compare with, prepared once for the whole class.
struct References {
  std::vector<RunOutcome> solution;                      ///< one per seed, when needed
  std::vector<std::optional<record::Screen>> pictures;   ///< per check: the screen check's PNG
  LimitNames limits;
  bool aboutRobot = false;  ///< a program that never places or moves the robot earns nothing
};

/// An assignment's verdict on a program.
struct Grading {
  std::vector<CheckResult> checks;  ///< one per check of the assignment, in its order
  /// Why nothing counts, before any check ("the program is empty"), or "".
  std::string gate;
};

/// An assignment's checks over a program's runs (one per seed, same order as the seeds).
Grading checkAssignment(const Assignment& assignment, const References& refs, const std::vector<RunOutcome>& runs);

// Pieces the checks are made of, exposed for tests.

/// "" when `got` equals `expected`, else where they first differ. `byLine`: compared line by
/// line, so a missing newline at the very end does not count.
std::string outputDifference(const std::string& expected, const std::string& got, bool byLine);
/// The share of pixels that differ, and how many; nullopt when the sizes differ.
struct PixelDifference {
  size_t differing = 0, total = 0;
  double share() const { return total ? static_cast<double>(differing) / static_cast<double>(total) : 0; }
};
std::optional<PixelDifference> compareImages(const render::RgbImage& a, const render::RgbImage& b);
/// The same for two screens as runs, in time proportional to the runs.
std::optional<PixelDifference> compareScreens(const record::Screen& a, const record::Screen& b);
/// Why a run cannot be graded at all (the process died, nothing ran), or "".
std::string unrunnable(const RunOutcome& run);
/// "the robot crashed at prog.bas:12:3 after 418 steps: robot crashed into an obstacle" style,
/// for a run that stopped with a runtime error or a limit (named as `limits` says, with the
/// loop it was in); "" for one that finished.
std::string stopDescription(const record::RunRecord& record, const LimitNames& limits = {});
/// The output as checks compare it: without input's prompts and echo unless `prompts`.
std::string comparedOutput(const RunOutcome& run, bool prompts);
/// A number of pixels for a message: "37", "37.5", "infinitely".
std::string pixels(double v);

}  // namespace rb::grade
