#pragma once
// What one run of a program left behind, as `rb test` grades it: rb check's diagnostics, how
// the run ended, the robot's final pose, the path it drove and the trail its pen drew. A child
// process (`rb test-job`, rb itself) runs the program and writes this record as JSON; the
// grading process reads it back. The same observer also feeds `rb trace`'s end record.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry.h"
#include "machine/interpreter.h"
#include "machine/machine.h"
#include "png_writer.h"

namespace rb::record {

/// A diagnostic as text fields: the file's name as the program named it, 1-based line and column.
struct DiagRecord {
  std::string file;
  uint32_t line = 0, col = 0;
  std::string severity;  ///< "error", "warning" or "note"
  std::string message;
  friend bool operator==(const DiagRecord&, const DiagRecord&) = default;
};

/// How a run ended, by name: "finished", "error" (a runtime error), "limit" (--max-steps or
/// --timeout), "stopped" (the host stopped it), "rejected" (load errors: nothing ran) or
/// "not-run" (something else prevented the run: a missing file, a bad events script).
std::string statusName(RunStatus status);
/// "max-steps" or "timeout" for a limit, "" otherwise.
std::string limitName(RunStatus status);

struct RunRecord {
  // rb check's view of the program: every diagnostic with warnings (and --target's), and the
  // exit status rb check would give (0, 65 errors, 66 no such file).
  int checkExit = 0;
  std::vector<DiagRecord> checkDiags;
  std::vector<DiagRecord> targetDiags;  ///< the extra warnings of --target rb9 and --portable, when asked for

  // The run, as `rb run` with the same options would do it.
  int exitCode = 0;                  ///< rb run's exit status
  std::string status = "not-run";    ///< see statusName()
  std::string limit;                 ///< see limitName()
  std::vector<DiagRecord> loadErrors;
  std::optional<DiagRecord> error;   ///< the runtime error or the limit that stopped the run
  bool crashed = false;              ///< the robot crashed into an obstacle
  uint64_t steps = 0;
  uint64_t seed = 0;

  bool located = false;              ///< rLocate placed the robot
  P2 pos;                            ///< final pose
  double heading = 0;
  bool penDown = false;
  Polylines path;                    ///< the robot's centre, one polyline per rLocate
  Polylines trail;                   ///< what the pen drew, one polyline per stroke
  bool truncated = false;            ///< path or trail reached PathRecorder::kMaxPoints
  bool screen = false;               ///< the final screen was written beside the record

  // What a grader asks of a run beyond its end (docs/teaching.md).
  /// False while only rb check's part is written (the child writes it before the run starts,
  /// so that a run killed at its time limit still has it).
  bool complete = true;
  uint64_t statements = 0;           ///< statements in the program and its includes
  uint64_t moves = 0;                ///< robot statements that placed, moved or turned the robot
  double radius = 20;                ///< the robot's radius (rLocate's)
  /// The line of the statement that brought the robot to each point of `path` (0: another file).
  std::vector<std::vector<uint32_t>> pathLines;
  /// Where each `input` left its mark in the output (byte offsets): its prompt from `start` to
  /// `promptEnd`, then the echo of the line read up to `end`.
  struct InputMark {
    uint64_t start = 0, promptEnd = 0, end = 0;
    friend bool operator==(const InputMark&, const InputMark&) = default;
  };
  std::vector<InputMark> inputs;
  /// A run stopped by a limit inside a loop: the loop's first and last line (0 when none).
  uint32_t loopFirst = 0, loopLast = 0;
  /// The colours a grader watches (avoid/touch): whether the robot's disc ever covered a pixel
  /// of each (0xRRGGBB), first where and on which line (the rule: colour_watch.h).
  struct Touch {
    uint32_t rgb = 0;
    bool touched = false;
    P2 at;
    uint32_t line = 0;
  };
  std::vector<Touch> touches;
  /// A world program run before the student's: why it failed, or "".
  std::string worldError;
  /// What the kernel could not put in force around the run (docs/confinement.md), or "".
  std::string confinement;
  /// Programs run after the student's, on the final state (post checks), in order.
  struct Post {
    std::string file;
    std::string output;                ///< what it printed
    std::optional<DiagRecord> error;   ///< its runtime error or limit
    bool ran = false;
  };
  std::vector<Post> posts;
};

/// What the program printed, without the prompts of `input` and the echo of what it read: the
/// echo's line end remains only where it ends a line the program printed on before the prompt.
/// Marks past the end of `output` (a cut output) are ignored.
std::string printedOutput(const std::string& output, const std::vector<RunRecord::InputMark>& marks);

/// Records the robot's path and pen trail from the events the Machine reports.
/// A program that moves forever would make them grow without end: each keeps at most
/// kMaxPoints points and then stops growing (`truncated`).
class PathRecorder : public RobotObserver {
 public:
  static constexpr size_t kMaxPoints = 100000;

  void robotEvent(const RobotEvent& e) override;

  Polylines path;
  Polylines trail;
  std::vector<std::vector<uint32_t>> pathLines;  ///< the statement's line per path point
  bool crashed = false;
  bool truncated = false;
  uint64_t moves = 0;  ///< Locate, Move and Turn events

 private:
  bool add(Polylines& lines, size_t& count, bool newLine, P2 p);
  void addPath(bool newLine, P2 p, uint32_t line);

  bool stroke_ = false;  ///< the last trail polyline is still being drawn
  size_t pathPoints_ = 0, trailPoints_ = 0;
};

/// A final screen as runs of one colour, row after row: what the checks compare (in time
/// proportional to the runs, not the pixels) and the pictures decode.
struct Screen {
  int width = 0, height = 0;
  std::vector<render::ColourRun> runs;
};
/// The runs of an image (a reference picture).
Screen screenOf(const render::RgbImage& image);
/// The image of the runs.
render::RgbImage imageOf(const Screen& screen);

/// The final screen travels beside the record as runs of one colour (render::composeRuns): a
/// few kilobytes where the picture is 1.4 MB. The file: "RBRUNS1 W H N\n", then N runs of two
/// little-endian 32-bit words (count, 0xRRGGBB).
std::string screenFileBytes(const std::vector<render::ColourRun>& runs, int width, int height);
bool writeScreenFile(const std::string& path, const std::vector<render::ColourRun>& runs, int width, int height,
                     std::string& error);
std::optional<Screen> readScreenFile(const std::string& path, std::string& error);

/// The record as one JSON object.
std::string recordToJson(const RunRecord& record);
/// Parses a record; nullopt with `error` set when the text is not one.
std::optional<RunRecord> recordFromJson(std::string_view text, std::string& error);

}  // namespace rb::record
