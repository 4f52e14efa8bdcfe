#pragma once
// Feedback pictures: what a student's robot did, drawn over what was asked, as a PNG with a
// legend. The teacher's picture shows the solution's trail and final screen; a student's
// picture (--student) never shows the solution's drawing, only the student's own work and what
// the assignment asked for (waypoints, regions to reach or avoid).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry.h"
#include "png_writer.h"

namespace rb::grade {

/// A region the assignment names, drawn with its label.
struct PictureRegion {
  enum Role { Goal, Avoid } role = Goal;  ///< ends-in / touch (green) or avoid (orange, hatched)
  record::Region region;
  std::string label;  ///< the check's name
};

/// Where a check failed (the robot entered an area, touched a colour, crashed...), marked with
/// a cross and the check's name.
struct PictureMark {
  record::P2 at;
  std::string label;
};

/// A colour an avoid or touch check watches: not drawn (it is on the screen), but named in the
/// legend with its swatch.
struct PictureColour {
  uint32_t rgb = 0;  ///< 0xRRGGBB
  std::string label;  ///< the check's name and the colour's ("walls: black")
  bool avoid = true;
};

struct PictureInput {
  record::Polylines student;                  ///< the student's trail
  /// The student's robot's path (its centre, from the recording), drawn whatever the pen did.
  record::Polylines studentPath;
  record::Polylines reference;                ///< the solution's trail (or the trail check's)
  /// The solution's final screen, shown faded (shared: a class's pictures all show the same one).
  std::shared_ptr<const render::RgbImage> background;
  std::shared_ptr<const render::RgbImage> studentScreen; ///< the student's final screen (student view)
  std::optional<record::P2> studentEnd;       ///< where the student's robot ended
  std::optional<record::P2> referenceEnd;
  double robotRadius = 20;
  /// A picture for the student: no solution (reference, background, referenceEnd are not
  /// drawn even when given); the student's own final screen faded behind their trail.
  bool studentView = false;
  std::vector<record::P2> waypoints;          ///< numbered in order (the visits checks)
  std::vector<PictureRegion> regions;
  std::vector<PictureColour> colours;         ///< colour checks, in the legend
  std::vector<PictureMark> failures;          ///< where checks failed
  std::string title;                          ///< the program's name, written at the top
};

/// The picture's size: the 800 x 600 arena (the screen) and a legend strip below it.
constexpr int kPictureWidth = 800;
constexpr int kArenaHeight = 600;
constexpr int kLegendHeight = 64;  ///< two rows of legend entries
constexpr int kPictureHeight = kArenaHeight + kLegendHeight;

/// The arena, and a legend strip below it naming everything drawn: the reference trail as a
/// wide light green band ("the solution's trail"), the robot's path as a thin pale red line
/// ("your robot's path"; also where the pen was up), the student's trail as a red line on top
/// ("your trail"), the places where checks failed as dark crosses with the check's name
/// ("where a check failed"), the colours colour checks watch as swatches ("keep off: walls:
/// black"), the robots' final positions as circles in the same colours, waypoints as
/// numbered blue markers, regions outlined (goals green, areas to avoid orange and hatched)
/// with their labels written in the arena. The title, when given, is at the top left (or at
/// another corner when the screen has something drawn there and that corner has not). Text is
/// drawn with the screen's embedded fonts (Liberation Sans), labels placed where they hide the
/// least of the trails.
render::RgbImage feedbackPicture(const PictureInput& input);

/// The legend's entries, in order, as feedbackPicture writes them: one for each kind of thing
/// the picture draws, none for what it does not ("your trail", "where your robot ended", "the
/// solution's trail", "where the solution's robot ended", "waypoints, in order", "reach: <label>"
/// / "keep out: <label>"). Regions without a label, or too many to fit the strip with theirs,
/// are named by their role only ("goal region(s)", "area(s) to avoid"). Texts are UTF-8.
std::vector<std::string> legendEntries(const PictureInput& input);

/// feedbackPicture() and legendEntries() for many pictures: the fonts loaded and the glyphs
/// drawn for one picture are kept for the next (a class's pictures share most of their words).
/// The pictures are the same as feedbackPicture's.
class PicturePainter {
 public:
  PicturePainter();
  ~PicturePainter();
  PicturePainter(const PicturePainter&) = delete;
  PicturePainter& operator=(const PicturePainter&) = delete;
  render::RgbImage picture(const PictureInput& input);
  std::vector<std::string> legend(const PictureInput& input);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Colours of the picture (0xRRGGBB), for the documentation and tests.
constexpr uint32_t kReferenceColour = 0x8FD98F;
constexpr uint32_t kStudentColour = 0xD01818;
constexpr uint32_t kWaypointColour = 0x1F5FD0;
constexpr uint32_t kGoalColour = 0x2E9E2E;
constexpr uint32_t kAvoidColour = 0xE05A00;
constexpr uint32_t kPathColour = 0xE89090;
constexpr uint32_t kFailColour = 0x8B0000;

}  // namespace rb::grade
