#pragma once
// The screen as a sixel image, for `rb run --tui --cells pixels` on terminals that show sixel
// graphics: the picture rb render writes (png_writer.h: the screen with the robot on top),
// scaled to the pixels the arena's cells cover and encoded by libsixel (Debian libsixel-dev).

#include <string>

#include "png_writer.h"

namespace rb::render {

/// `image` scaled (nearest neighbour) to width x height pixels, as the bytes that make a
/// terminal show it at the cursor (DCS q ... ST). "" when the size is empty or libsixel fails.
std::string sixelImage(const RgbImage& image, int width, int height);

}  // namespace rb::render
