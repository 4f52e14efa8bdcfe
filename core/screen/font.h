#pragma once
// Bitmap fonts for text on the screen. rb compiles real console fonts (Debian's VGA and
// Terminus PSF fonts) into the binary at build time, so text is drawn exactly, pixel for pixel,
// and the robot senses it like any drawing.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rb {

namespace fontdata {
struct EmbeddedFont {
  const char* name;
  int bold;
  const unsigned char* data;  ///< a PSF1 or PSF2 file
  size_t size;
};
extern const EmbeddedFont kFonts[];
extern const size_t kFontCount;
}  // namespace fontdata

/// One fixed-width bitmap font, indexed by Latin-1 character code.
class BitmapFont {
 public:
  /// Decodes a PSF1 or PSF2 file (with its Unicode table).
  BitmapFont(const unsigned char* data, size_t size, bool bold);

  int width() const { return width_; }
  int height() const { return height_; }
  bool bold() const { return bold_; }
  /// Whether pixel (x, y) of the glyph for `ch` is set.
  bool pixel(unsigned char ch, int x, int y) const {
    const uint8_t* g = glyphs_.data() + static_cast<size_t>(map_[ch]) * bytesPerGlyph_;
    return (g[y * rowBytes_ + x / 8] >> (7 - x % 8)) & 1;
  }

 private:
  int width_ = 8, height_ = 16, rowBytes_ = 1, bytesPerGlyph_ = 16;
  bool bold_ = false;
  std::vector<uint8_t> glyphs_;
  uint16_t map_[256] = {};
};

/// The font of `print` text: 8 x 16 pixels (VGA).
const BitmapFont& consoleFont();
/// The font for xyText at a given pixel height: the tallest embedded font not taller than it
/// (12 to 32 pixels; bold when asked). Larger sizes use the 32-pixel font scaled up.
const BitmapFont& textFont(int pixelHeight, bool bold);

}  // namespace rb
