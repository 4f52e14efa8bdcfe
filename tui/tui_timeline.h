#pragma once
// The live view's timeline: what an earlier step of the run looked like, from the run's
// recording (machine/recording.h: each statement with the robot's pose, the screen as
// keyframes, the output so far), and the position bar in the output pane's header line. Pure
// functions of the recording and the text, tested without a terminal; tui/tui_host.cpp shows
// them. Going back is looking: the program stays where it is, and resuming goes on from there.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "arena_view.h"
#include "machine/recording.h"
#include "screen/canvas.h"

namespace rb::tui {

/// The budget of the live view's recording: every statement of a run of up to 2^20 (about a
/// million) is kept (the steps may take 3/8 of the budget, and 2^20 of them take 80 MiB), with
/// the screens it drew as they fit; a longer run keeps every 2nd, 4th, ... statement, evenly
/// (Recording's thinning). *rb's choice: a million statements is a minute of a busy loop.*
constexpr size_t kTimelineBudget = size_t{224} << 20;

/// An earlier step as the view shows it.
struct PastStep {
  RecordedStep step;  ///< a copy: the recording may grow once the run goes on
  Pixels screen;               ///< the screen as that statement started
  render::RobotView robot;
  std::optional<double> range;  ///< the last rRange reading before it
};

/// Step `index` of `rec.steps()` with its screen decoded from the keyframes.
PastStep pastStep(const Recording& rec, size_t index);

/// The step a jump of `fraction` of the whole run (negative: back) from `index` lands on: the
/// kept step at or before the statement that far away, at least one step from `index` while
/// there is one in that direction, clamped to the recording.
size_t jumpFrom(const Recording& rec, size_t index, double fraction);

/// "step 1,234" as the view numbers them: a statement by its place in the run counting from 1,
/// the recording's last step (after the end) as "the end".
std::string stepName(const RecordedStep& s);
/// 1234567 -> "1,234,567".
std::string grouped(uint64_t n);

/// The output pane's header line while the timeline is shown (paused, or at the end):
/// "-- step 997 of 1,000 [########|.] --", `width` cells. `at` and `count`: the shown step's
/// place among the kept steps. `barCol` and `barWidth` receive where the bar's inside is (a
/// click there jumps: stepAtColumn); barWidth 0 when no bar fits.
std::string timelineRule(int width, const std::string& label, size_t at, size_t count, int& barCol,
                         int& barWidth);
/// The kept step a click on column `col` of the bar means (see timelineRule).
size_t stepAtColumn(int col, int barCol, int barWidth, size_t count);

/// The last `maxLines` lines of `text` (oldest first); the last one may be a line not yet ended.
/// What output had been printed by a step is text[0, step.output).
std::vector<std::string_view> lastLines(std::string_view text, size_t maxLines);

}  // namespace rb::tui
