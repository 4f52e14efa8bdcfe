#pragma once
// Fonts for text on the screen. rb compiles the Liberation fonts into the binary at build time
// (core/screen/fonts/embed_fonts.cmake) and rasterizes them with FreeType, monochrome (no
// anti-aliasing: a pixel is drawn or not), from memory. So text is drawn the same way on every
// run, pixel for pixel, and the robot senses it like any drawing.
//
// Liberation Mono, Sans and Serif have the widths of Courier New, Arial and Times New Roman:
// text takes the room on rb's screen that it took on RobotBASIC's.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace rb {

namespace fontdata {
struct EmbeddedFont {
  const char* name;           ///< "mono", "sans_bold", "serif_bold_italic", ...
  const unsigned char* data;  ///< a TrueType file
  size_t size;
};
extern const EmbeddedFont kFonts[];
extern const size_t kFontCount;
}  // namespace fontdata

/// The three faces. Mono is Courier New's twin, the face of `print` and `xyString`.
enum class Typeface : uint8_t { Mono, Sans, Serif };

/// The face an xyText font name asks for: "" is the default face (Mono, as print); a name with
/// "sans" is Sans; Courier and other fixed-width names ("mono", "consol", "fixed", "terminal",
/// "typewriter") are Mono; Times and other serif names ("serif", "roman", "georgia",
/// "garamond", "palatino", "cambria", "book") are Serif; any other name (Arial, Verdana,
/// Tahoma, ...) is Sans, Windows' usual substitute. Case is ignored.
Typeface typefaceForName(std::string_view name);

/// The CSS family list for a face (SVG): the Windows face first, then Liberation, then generic.
const char* cssFontFamily(Typeface face);

/// A font at a size: what a text call draws with.
struct FontKey {
  Typeface face = Typeface::Mono;
  bool bold = false, italic = false;
  int pixelSize = 13;  ///< the em in pixels (points * 96 / 72, rounded): 13 is 10 points
  friend bool operator==(const FontKey&, const FontKey&) = default;
};

/// The pixel size of a font of `points` points at 96 dots per inch (as Windows rounds it).
int pixelSizeForPoints(double points);

/// Vertical metrics in whole pixels, measured from the top of the text's cell, Windows'
/// way: the cell is ascent + descent high (the font's usWinAscent and usWinDescent).
struct FontMetrics {
  int ascent = 0;             ///< from the cell's top to the baseline
  int descent = 0;            ///< below the baseline
  int lineHeight = 0;         ///< ascent + descent
  int underlineTop = 0;       ///< first row of the underline, from the cell's top
  int underlineThickness = 1;
  int strikeoutTop = 0;       ///< first row of the strike-out line, from the cell's top
  int strikeoutThickness = 1;
};

/// One rasterized character: a monochrome bitmap placed relative to the pen on the baseline.
struct Glyph {
  int left = 0;     ///< from the pen to the bitmap's first column
  int top = 0;      ///< from the baseline up to the bitmap's first row
  int width = 0, height = 0;
  int advance = 0;  ///< how far the pen moves, in whole pixels
  /// The bitmap lies inside the character's cell: between the pen and the next pen position,
  /// within the line's height (FontMetrics::lineHeight below the cell's top).
  bool inCell = true;
  std::vector<uint8_t> bits;  ///< width * height, 1 where the pixel is drawn
  bool pixel(int x, int y) const { return bits[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] != 0; }
  /// The drawn pixels as horizontal runs, so drawing visits only them.
  struct Run {
    int16_t x, y, length;
  };
  std::vector<Run> runs;
};

/// The fonts of one screen: FreeType over the embedded fonts, with the glyphs it rasterized
/// kept for reuse. Characters are Latin-1 bytes; one the font lacks is drawn as '?'.
class FontRenderer {
 public:
  FontRenderer();
  ~FontRenderer();
  FontRenderer(const FontRenderer&) = delete;
  FontRenderer& operator=(const FontRenderer&) = delete;

  const FontMetrics& metrics(const FontKey& key);
  const Glyph& glyph(const FontKey& key, unsigned char ch);
  /// The glyphs of the first `keep` characters of `text` (at most), in `out` (replacing what it
  /// held): one font lookup for the whole string. The glyphs live as long as the renderer.
  /// Returns the width of the whole text, the sum of the advances, at most kMaxTextWidth.
  int glyphs(const FontKey& key, std::string_view text, std::vector<const Glyph*>& out, size_t keep);
  /// The widest a text is measured (pixels): far past any screen, and far from int's limit
  /// (a 64-million-character string at 200 points would overflow it).
  static constexpr int kMaxTextWidth = 1 << 24;
  /// The width of a string: the sum of its advances, at most kMaxTextWidth.
  int width(const FontKey& key, std::string_view text);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rb
