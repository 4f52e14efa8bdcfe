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

namespace rb::grade {

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
  std::vector<DiagRecord> targetDiags;  ///< the extra warnings of --target rb9, when asked for

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
};

/// Records the robot's path and pen trail from the events the Machine reports.
/// A program that moves forever would make them grow without end: each keeps at most
/// kMaxPoints points and then stops growing (`truncated`).
class PathRecorder : public RobotObserver {
 public:
  static constexpr size_t kMaxPoints = 100000;

  void robotEvent(const RobotEvent& e) override;

  Polylines path;
  Polylines trail;
  bool crashed = false;
  bool truncated = false;

 private:
  bool add(Polylines& lines, size_t& count, bool newLine, P2 p);

  bool stroke_ = false;  ///< the last trail polyline is still being drawn
  size_t pathPoints_ = 0, trailPoints_ = 0;
};

/// The final screen travels beside the record as a binary PPM file (P6, 8-bit RGB).
bool writeScreenFile(const std::string& path, const render::RgbImage& image, std::string& error);
std::optional<render::RgbImage> readScreenFile(const std::string& path, std::string& error);

/// The record as one JSON object.
std::string recordToJson(const RunRecord& record);
/// Parses a record; nullopt with `error` set when the text is not one.
std::optional<RunRecord> recordFromJson(std::string_view text, std::string& error);

}  // namespace rb::grade
