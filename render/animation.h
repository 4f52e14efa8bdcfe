#pragma once
// Replays of a recorded run (core/machine/recording.h): an animated GIF (giflib), an animated
// SVG that plays in any browser without a script (CSS or SMIL), and one self-contained HTML page
// with a player (the screen on a canvas, play/pause, speed, a timeline slider, step forward and
// back, the source with the current line highlighted, the output so far, the robot's pose and
// sensors). `rb render --animate OUT` writes them; rb test's replays use the same writers.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "machine/recording.h"
#include "png_writer.h"

namespace rb::render {

/// The valid ranges of the options (rb render checks them before it runs anything).
constexpr double kMinFps = 0.1, kMaxFps = 100;
constexpr double kMaxDuration = 3600;  ///< seconds (--duration), from 1 / kMaxFps
constexpr double kMaxHold = 600;       ///< seconds (a GIF frame lasts at most 655.35 s)

/// Which moments of the recording become frames, and how fast they play.
struct AnimationOptions {
  double fps = 10;                      ///< frames per second of the animation (0.1 .. 100)
  std::optional<double> duration;       ///< seconds the whole run should take (frames sampled)
  std::optional<uint64_t> every;        ///< one frame every N statements
  double hold = 2;                      ///< seconds the last frame stays before a GIF loops
  int scale = 1;                        ///< pixels per screen pixel (1 .. kMaxScale)
  size_t maxFrames = 2000;              ///< frames are sampled evenly down to this many
  bool glide = true;                    ///< long moves and turns in frames of their own (below)
  bool autoplay = false;                ///< the HTML player starts playing once it is in view
};

/// Gliding: by default (one frame per visible change), a move of the robot longer than
/// kGlidePixels between two recorded steps, or a turn of more than kGlideDegrees, is shown in
/// frames of its own, at most kGlidePixels or kGlideDegrees apart, the trail drawn up to the
/// robot as it goes. While the frames with the glides would pass maxFrames, the glides' steps
/// double (20 pixels, 40..) until they fit; a run whose frames fill maxFrames without them does
/// not glide (its frames are the same as without gliding). --every and --duration never glide.
constexpr double kGlidePixels = 10, kGlideDegrees = 15;

/// What the HTML player shows beside the screen: the program's text.
struct PlayerSource {
  std::string name;     ///< the file's name, shown as the title
  std::string text;     ///< the main file's text (its lines, for highlighting)
  uint32_t file = 0;    ///< the file index of the main file in the recording's locations
};

/// The recorded steps that become frames (indices into recording.steps()), first and last
/// included, evenly sampled by the options.
std::vector<size_t> animationFrames(const Recording& recording, const AnimationOptions& options);

/// The picture of one recorded step: the keyframe in effect with the robot drawn at its pose,
/// the same pixels `rb render` writes for the run stopped at that step.
RgbImage frameImage(const Recording& recording, size_t step, int scale = 1);

/// An animated GIF (GIF89a, looping, the RobotBASIC palette where it fits, frame delays from the
/// fps, the last frame held). Throws std::runtime_error when giflib fails.
std::vector<uint8_t> encodeGif(const Recording& recording, const AnimationOptions& options);
/// An animated SVG (no script): the frames in turn, the last one held.
std::string animatedSvg(const Recording& recording, const AnimationOptions& options);
/// One self-contained HTML page (no network: everything inline) with the player.
std::string htmlPlayer(const Recording& recording, const PlayerSource& source, const AnimationOptions& options);

/// The frames' moments: `steps` as animationFrames() gives them and, for each, the second at
/// which it appears (k / fps, or spread over --duration).
/// A frame inside a glide shows step `steps[k]` on its way to the next recorded step: part
/// `part[k]` of `parts[k]` (part 0: the step itself, as every frame without gliding).
struct FrameTimes {
  std::vector<size_t> steps;
  std::vector<double> seconds;
  std::vector<uint32_t> part, parts;
};

/// The robot part of the way from recorded step `step` to the next (part of parts, 0 < part <
/// parts): the centre on the segment between the two (a move), or the heading turned the short
/// way between the two (a turn); the radius and colour of the step. As the HTML player draws it.
struct GlidePose {
  double x = 0, y = 0, radius = 0;
  double dx = 0, dy = -1;  ///< the heading as a unit vector (0 degrees up, clockwise)
};
/// Whether the robot moves or turns between recorded steps `step` and `step + 1` so that a
/// glide can show it, and how far (pixels or degrees; 0: it cannot glide).
double glideExtent(const Recording& recording, size_t step, bool* turn = nullptr);
GlidePose glidePose(const Recording& recording, size_t step, uint32_t part, uint32_t parts);
/// The picture part of the way from `step` to the next: the screen of `step` with the pixels the
/// next step changed drawn where they lie behind the robot along its move (their projection on
/// the move at most the robot's), and the robot at glidePose(). Parts 0 and `parts` are
/// frameImage() of `step` and `step + 1`.
RgbImage glideImage(const Recording& recording, size_t step, uint32_t part, uint32_t parts, int scale = 1);
FrameTimes animationTimes(const Recording& recording, const AnimationOptions& options);

/// The format OUT's extension names, in any case: "gif", "svg", "html" (.html or .htm), or ""
/// when it names none of them.
std::string animationFormat(const std::string& path);

/// The animation in `format` ("gif", "svg" or "html") as bytes; throws std::exception when it
/// cannot be made.
std::string encodeAnimation(const std::string& format, const Recording& recording, const PlayerSource& source,
                            const AnimationOptions& options);

/// Writes the animation OUT's extension names (.gif, .svg, .html or .htm). On failure returns
/// false with a message naming the file (or the unknown extension) in `error`.
bool writeAnimation(const std::string& path, const Recording& recording, const PlayerSource& source,
                    const AnimationOptions& options, std::string& error);

}  // namespace rb::render
