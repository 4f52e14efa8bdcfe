#pragma once
// One recording of a run, which every replay reads: `rb render --animate` (GIF, SVG, HTML),
// rb test's replays and the live view's timeline. It keeps, as the machine produced them, the
// statement about to run at each step with the robot's pose, what the robot's sensors read, the
// output and what `input` read, and the screen as keyframes: the screen's colours as runs of one
// colour, taken before a statement whenever the screen changed since the last one.
//
// Bounded in memory (`budget`, 64 MiB by default): steps are kept every `stepStride()` steps
// and keyframes at most every `frameStride()` steps; when what is kept passes half the budget,
// the stride doubles and every other entry goes. A short program is kept whole, statement by
// statement; a program of millions of steps keeps a sample of them, evenly spread, whatever its
// length. Nothing here knows a file format: render/ writes the animations.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/diagnostic.h"
#include "base/source.h"
#include "machine/interpreter.h"
#include "machine/machine.h"
#include "screen/canvas.h"

namespace rb {

/// A run of pixels of one colour (a colour number, as the canvas keeps them), row-major.
struct ScreenRun {
  uint32_t count = 0;
  Colour colour = 0;
  friend bool operator==(const ScreenRun&, const ScreenRun&) = default;
};
/// A run's colour that means "as in the frame before" (no colour number is this large).
constexpr Colour kSameColour = 0xFFFFFFFFu;

/// The screen as the recording keeps it: some frames whole (see kFullAfter), the others as what
/// changed since the frame before (runs of kSameColour where nothing did).
struct RecordedFrame {
  uint64_t step = 0;  ///< the screen as statement `step` (0-based) starts
  std::vector<ScreenRun> runs;
  bool full = false;
};

/// One statement about to run, and the state it starts from.
struct RecordedStep {
  uint64_t step = 0;       ///< statements run before it
  SourceLoc loc;           ///< the statement (loc.line 0: the end of the run)
  // Doubles, as the robot keeps them: the replays draw the robot from these, pixel for pixel as
  // `rb render` draws it from the robot itself (a float moves a pixel on the rim now and then).
  double x = 0, y = 0;     ///< the robot's centre
  double heading = 0;      ///< degrees, 0 up, clockwise
  double radius = 20;
  Colour robotColour = 0;
  bool located = false;    ///< rLocate placed the robot
  bool pen = false;        ///< the pen is down
  uint32_t frame = 0;      ///< the keyframe in effect (an index into frames())
  uint64_t output = 0;     ///< bytes of output written before it
};

/// A sensor read or an input line, with the step that did it.
struct RecordedEvent {
  uint64_t step = 0;
  enum Kind : uint8_t { Sensor, Input } kind = Sensor;
  std::string what;  ///< the sensor's name ("rRange") or the line input read
  double value = 0;  ///< the sensor's reading
};

class Recording {
 public:
  static constexpr size_t kDefaultBudget = size_t{64} << 20;
  /// At most this much output is kept (the rest is counted, not kept).
  static constexpr size_t kOutputCap = size_t{1} << 20;
  /// A frame is kept whole again once the changes kept since the last whole frame take as many
  /// bytes as it does, and at least this many: decoding any frame then reads at most about twice
  /// a whole frame's bytes, and whole frames take at most half the frames' memory, however busy
  /// the screen (a screen of single pixels is a run per pixel: megabytes a frame).
  static constexpr size_t kFullAfter = size_t{64} << 10;

  explicit Recording(size_t budget = kDefaultBudget) : budget_(budget) {}

  // ---- fed while the program runs

  /// Before each statement (Host::onLine): the statement and the machine as it starts.
  void statement(SourceLoc loc, Machine& machine);
  /// Program output as the host writes it (input's echo included).
  void output(std::string_view text);
  /// A line `input` read.
  void input(std::string_view line);
  /// A robot event (sensor readings are kept; the pose comes from the machine).
  void robotEvent(const RobotEvent& e);
  /// After the run: the final screen and pose as a last step (loc.line 0), and how it ended.
  void finish(Machine& machine, const RunResult& result);

  // ---- read by the replays

  const std::vector<RecordedStep>& steps() const { return steps_; }
  const std::vector<RecordedFrame>& frames() const { return frames_; }
  const std::vector<RecordedEvent>& events() const { return events_; }
  /// The output kept (the first kOutputCap bytes), and how many bytes there were in all.
  const std::string& output() const { return output_; }
  uint64_t outputBytes() const { return outputBytes_; }
  /// Statements the run executed in all (the last step's `step`).
  uint64_t totalSteps() const { return total_; }
  bool finished() const { return finished_; }
  /// How the run ended ("finished", or the runtime error or limit), set by finish().
  const std::optional<Diagnostic>& error() const { return error_; }
  RunStatus status() const { return status_; }
  /// Steps and keyframes are kept every this many steps (1 while everything fits).
  uint64_t stepStride() const { return stepStride_; }
  uint64_t frameStride() const { return frameStride_; }
  /// Memory the recording holds now, about.
  size_t bytes() const { return stepBytes() + frameBytes_ + output_.size() + eventBytes_; }

  /// The screen of a keyframe, pixel by pixel (Canvas::kWidth x kHeight colour numbers).
  std::vector<Colour> screen(size_t frame) const;
  /// The last kept step at or before `step` (steps() must not be empty).
  size_t stepAt(uint64_t step) const;

 private:
  size_t stepBytes() const { return steps_.capacity() * sizeof(RecordedStep); }
  void keyframe(Machine& machine, uint64_t step);
  /// Changes whenever what a viewer sees changes: the canvas's version while the canvas is
  /// shown, the count of flips (tagged apart) while flip on shows the last flip's screen.
  static uint64_t shownVersion(const Machine& machine);
  /// The frame of `pixels`, whole or as changes since `before` (what the frame before shows).
  RecordedFrame encode(const Colour* pixels, const std::vector<Colour>& before, uint64_t step, bool full) const;
  RecordedStep stateOf(SourceLoc loc, const Machine& machine, uint64_t step) const;
  /// Halves what is kept when it has grown past half the budget.
  void thinSteps();
  void thinFrames();
  void thinFramesOnce();

  size_t budget_;
  std::vector<RecordedStep> steps_;
  std::vector<RecordedFrame> frames_;
  std::vector<RecordedEvent> events_;
  std::string output_;
  uint64_t outputBytes_ = 0;
  uint64_t total_ = 0;         ///< statements seen so far
  uint64_t stepStride_ = 1, frameStride_ = 1;
  uint64_t shownVersion_ = 0;  ///< shownVersion() at the last keyframe
  bool lastShownFlip_ = false;  ///< the last keyframe is of a flip's screen, not the canvas
  uint64_t lastFrameStep_ = 0;
  size_t frameBytes_ = 0, eventBytes_ = 0;
  Pixels last_;  ///< the screen of the last frame kept (large memory, as the canvas's)
  size_t sinceFull_ = 0, lastFull_ = 0;  ///< bytes of changes since the last whole frame, and its size
  bool finished_ = false;
  std::optional<Diagnostic> error_;
  RunStatus status_ = RunStatus::Finished;
};

/// A screen's colours as runs, and back.
std::vector<ScreenRun> screenRuns(const Colour* pixels, size_t count);
std::vector<Colour> screenFromRuns(const std::vector<ScreenRun>& runs, size_t count);

}  // namespace rb
