#pragma once
// Feedback pictures: a student's pen trail drawn over the solution's, as a PNG.

#include <optional>

#include "geometry.h"
#include "png_writer.h"

namespace rb::grade {

struct PictureInput {
  Polylines student;                          ///< the student's trail
  Polylines reference;                        ///< the solution's trail (or the trail check's)
  std::optional<render::RgbImage> background; ///< the solution's final screen, shown faded
  std::optional<P2> studentEnd;               ///< where the student's robot ended
  std::optional<P2> referenceEnd;
  double robotRadius = 20;
};

/// An 800 x 600 picture: the solution's screen faded (or white), the reference trail as a wide
/// light green band, the student's trail as a thin red line on top, and the robots' final
/// positions as circles in the same colours.
render::RgbImage feedbackPicture(const PictureInput& input);

/// Colours of the picture (0xRRGGBB), for the documentation and tests.
constexpr uint32_t kReferenceColour = 0x8FD98F;
constexpr uint32_t kStudentColour = 0xD01818;

}  // namespace rb::grade
