#pragma once
// The screen as an RGB image: scaled by a whole factor (nearest neighbour) with the robot drawn
// on top, encoded as PNG with libpng. The robot is never part of the screen's pixels, so it is
// drawn here (robot_image.h): a 3-pixel circle outline inside its rim and a 3-pixel line from
// the centre to the rim toward its heading.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "arena_view.h"
#include "screen/canvas.h"

namespace rb::render {

/// An 8-bit RGB image, row-major, three bytes per pixel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  ///< width * height * 3 bytes

  /// 0xRRGGBB of pixel (x, y); the caller keeps (x, y) inside the image.
  uint32_t pixel(int x, int y) const {
    const uint8_t* p = rgb.data() + (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
    return static_cast<uint32_t>(p[0]) << 16 | static_cast<uint32_t>(p[1]) << 8 | p[2];
  }
  /// Sets pixel (x, y) to 0xRRGGBB; the caller keeps (x, y) inside the image.
  void set(int x, int y, uint32_t colour) {
    uint8_t* p = rgb.data() + (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
    p[0] = static_cast<uint8_t>(colour >> 16);
    p[1] = static_cast<uint8_t>(colour >> 8);
    p[2] = static_cast<uint8_t>(colour);
  }
};

/// The largest --scale: 6400 x 4800 pixels, about 90 MB of RGB.
constexpr int kMaxScale = 8;

/// The 800 x 600 screen (`pixels`: row-major colour numbers) scaled by `scale` (1..kMaxScale,
/// clamped), nearest neighbour, without the robot.
RgbImage screenImage(const Pixels& pixels, int scale);

/// Draws the robot onto an image of the screen made with `scale`: a circle outline 3 screen
/// pixels thick just inside its rim and a line as thick from its centre to the rim in the
/// heading direction, both in the robot's colour (robot_image.h). Nothing is drawn when the
/// robot is not visible.
void drawRobot(RgbImage& image, const RobotView& robot, int scale);

/// screenImage() with drawRobot() on top: the picture `rb render` writes.
RgbImage composeImage(const Pixels& pixels, const RobotView& robot, int scale);

/// A run of pixels of one colour, in row-major order.
struct ColourRun {
  uint32_t count = 0;
  uint32_t rgb = 0;  ///< 0xRRGGBB
  friend bool operator==(const ColourRun&, const ColourRun&) = default;
};

/// composeImage()'s picture at scale 1 as runs of one colour (a screen is mostly long runs):
/// the same pixels, found without making the 1.4 MB image. Runs go on across rows.
std::vector<ColourRun> composeRuns(const Pixels& pixels, const RobotView& robot);
/// The image the runs describe (width x height pixels; what the runs do not cover is black).
RgbImage imageFromRuns(const std::vector<ColourRun>& runs, int width, int height);

/// The image as the bytes of a PNG file, no time stamp, so the same image always gives the same
/// bytes. An image of at most 256 colours (most screens) is written with a palette of them in
/// the order they first appear, at 1, 2, 4 or 8 bits a pixel (the fewest that hold them),
/// unfiltered; one of more colours as 8-bit RGB, each row with the "up" filter. Both with
/// zlib's level 3 and an sRGB chunk. Decoded, either gives back the image's pixels exactly.
/// Throws std::runtime_error when libpng fails or the image has no pixels, std::bad_alloc when
/// memory runs out.
std::vector<uint8_t> encodePng(const RgbImage& image);

/// Encodes the image and writes it to `path`. On failure returns false with a message naming
/// the file in `error`.
bool writePngFile(const std::string& path, const RgbImage& image, std::string& error);

/// Decodes a PNG file into 8-bit RGB (any PNG libpng reads; alpha is composed onto black).
/// Used by the tests to check the pixels rb render wrote. nullopt with `error` set on failure.
std::optional<RgbImage> readPngFile(const std::string& path, std::string& error);

/// Writes `bytes` to `path`. A regular file (or a new one) is written under a temporary name and
/// renamed over it, and so is a symbolic link to a file (replaced, never followed: a link planted
/// in a class folder must not lead rb to overwrite another file); a FIFO or a device, or a link
/// to one (/dev/stdout), is written to as it is and never replaced by a file. On failure returns false
/// with a message naming the file and the reason in `error`.
bool writeFileBytes(const std::string& path, const void* bytes, size_t size, std::string& error);

/// Makes the folder the user named for what rb writes (--pictures DIR, --out DIR), and only it:
/// its parent must exist (a typo never makes a tree of folders). True when it is there.
bool makeFolder(const std::string& path, std::string& error);

}  // namespace rb::render
