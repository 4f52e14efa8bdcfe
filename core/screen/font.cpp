#include "screen/font.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_DRIVER_H
#include FT_MODULE_H
#include FT_SIZES_H
#include FT_TRUETYPE_TABLES_H

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>

namespace rb {

namespace {

bool contains(const std::string& haystack, std::initializer_list<const char*> needles) {
  for (const char* n : needles)
    if (haystack.find(n) != std::string::npos) return true;
  return false;
}

/// Font units scaled to pixels and rounded.
int scaled(long units, int pixelSize, int unitsPerEm) {
  return static_cast<int>(std::lround(static_cast<double>(units) * pixelSize / unitsPerEm));
}

}  // namespace

Typeface typefaceForName(std::string_view name) {
  std::string n;
  for (char c : name) n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (n.find_first_not_of(' ') == std::string::npos) return Typeface::Mono;
  if (contains(n, {"sans"})) return Typeface::Sans;
  if (contains(n, {"courier", "mono", "consol", "fixed", "terminal", "typewriter"})) return Typeface::Mono;
  if (contains(n, {"times", "serif", "roman", "georgia", "garamond", "palatino", "cambria", "book"}))
    return Typeface::Serif;
  return Typeface::Sans;
}

const char* cssFontFamily(Typeface face) {
  switch (face) {
    case Typeface::Mono: return "'Courier New', 'Liberation Mono', monospace";
    case Typeface::Sans: return "Arial, 'Liberation Sans', sans-serif";
    case Typeface::Serif: return "'Times New Roman', 'Liberation Serif', serif";
  }
  return "monospace";
}

int pixelSizeForPoints(double points) {
  if (!std::isfinite(points)) return 1;
  return static_cast<int>(std::clamp(std::lround(points * 96.0 / 72.0), 1L, 10000L));
}

struct FontRenderer::Impl {
  /// One size of one face: its metrics and the glyphs rasterized so far.
  struct Sized {
    FT_Size size = nullptr;
    FontMetrics metrics;
    std::array<std::optional<Glyph>, 256> glyphs;
  };

  FT_Library library = nullptr;
  std::array<FT_Face, 12> faces{};  ///< by faceIndex(), loaded when first used
  std::map<std::tuple<int, int>, Sized> sizes;  ///< (face index, pixel size)

  Impl() {
    if (FT_Init_FreeType(&library) != 0) throw std::bad_alloc();
    // The bytecode interpreter is fixed, whatever FREETYPE_PROPERTIES says, so text is
    // rasterized the same way everywhere.
    FT_UInt version = TT_INTERPRETER_VERSION_40;
    FT_Property_Set(library, "truetype", "interpreter-version", &version);
  }
  ~Impl() {
    for (FT_Face f : faces)
      if (f) FT_Done_Face(f);
    FT_Done_FreeType(library);
  }

  static int faceIndex(const FontKey& key) {
    return static_cast<int>(key.face) * 4 + (key.bold ? 1 : 0) + (key.italic ? 2 : 0);
  }

  FT_Face face(int index) {
    if (faces[static_cast<size_t>(index)]) return faces[static_cast<size_t>(index)];
    static constexpr const char* kNames[12] = {"mono",  "mono_bold",  "mono_italic",  "mono_bold_italic",
                                               "sans",  "sans_bold",  "sans_italic",  "sans_bold_italic",
                                               "serif", "serif_bold", "serif_italic", "serif_bold_italic"};
    const fontdata::EmbeddedFont* font = nullptr;
    for (size_t i = 0; i < fontdata::kFontCount; ++i)
      if (std::strcmp(fontdata::kFonts[i].name, kNames[index]) == 0) font = &fontdata::kFonts[i];
    if (!font) throw std::runtime_error(std::string("font ") + kNames[index] + " is not compiled into rb");
    FT_Face f = nullptr;
    if (FT_New_Memory_Face(library, font->data, static_cast<FT_Long>(font->size), 0, &f) != 0)
      throw std::runtime_error(std::string("embedded font ") + kNames[index] + " cannot be read");
    faces[static_cast<size_t>(index)] = f;
    return f;
  }

  /// The size last asked for: text asks for the same one character after character.
  int lastIndex = -1, lastPx = -1;
  Sized* last = nullptr;

  /// One size of one face; FreeType's current size is set only when a glyph is rasterized.
  Sized& sized(const FontKey& key) {
    const int index = faceIndex(key);
    const int px = std::max(1, key.pixelSize);
    if (index == lastIndex && px == lastPx) return *last;
    auto [it, fresh] = sizes.try_emplace({index, px});
    Sized& s = it->second;
    lastIndex = index, lastPx = px, last = &s;
    if (!fresh) return s;
    FT_Face f = face(index);
    if (FT_New_Size(f, &s.size) != 0 || FT_Activate_Size(s.size) != 0 ||
        FT_Set_Pixel_Sizes(f, 0, static_cast<FT_UInt>(px)) != 0) {
      sizes.erase(it);
      lastIndex = -1, last = nullptr;
      throw std::runtime_error("cannot set a font size of " + std::to_string(px) + " pixels");
    }
    // Windows' cell: usWinAscent above the baseline, usWinDescent below (the hhea values when a
    // font has no OS/2 table). Underline from the post table, strike-out from OS/2.
    const int upem = f->units_per_EM > 0 ? f->units_per_EM : 2048;
    long winAscent = f->ascender, winDescent = -f->descender;
    long strikePos = upem / 4, strikeSize = upem / 20;
    if (auto* os2 = static_cast<TT_OS2*>(FT_Get_Sfnt_Table(f, FT_SFNT_OS2)); os2 && os2->version != 0xFFFF) {
      winAscent = os2->usWinAscent;
      winDescent = os2->usWinDescent;
      strikePos = os2->yStrikeoutPosition;
      strikeSize = os2->yStrikeoutSize;
    }
    FontMetrics& m = s.metrics;
    m.ascent = scaled(winAscent, px, upem);
    m.descent = scaled(winDescent, px, upem);
    m.lineHeight = std::max(1, m.ascent + m.descent);
    // underline_position is the centre of the underline (negative: below the baseline).
    m.underlineThickness = std::max(1, scaled(f->underline_thickness, px, upem));
    m.underlineTop = m.ascent - scaled(f->underline_position, px, upem) - m.underlineThickness / 2;
    m.underlineTop = std::clamp(m.underlineTop, 0, std::max(0, m.lineHeight - m.underlineThickness));
    // yStrikeoutPosition is the top of the strike-out stroke above the baseline.
    m.strikeoutThickness = std::max(1, scaled(strikeSize, px, upem));
    m.strikeoutTop = std::clamp(m.ascent - scaled(strikePos, px, upem), 0, std::max(0, m.lineHeight - 1));
    return s;
  }

  /// Rasterizes a character of one size into its slot of s.glyphs.
  void load(Sized& s, const FontKey& key, unsigned char ch) {
    FT_Activate_Size(s.size);
    Glyph& g = s.glyphs[ch].emplace(rasterize(face(faceIndex(key)), ch));
    const int top = s.metrics.ascent - g.top;
    g.inCell = g.width == 0 || g.height == 0 ||
               (g.left >= 0 && g.left + g.width <= g.advance && top >= 0 && top + g.height <= s.metrics.lineHeight);
  }

  Glyph rasterize(FT_Face f, unsigned char ch) {
    FT_UInt index = FT_Get_Char_Index(f, ch);
    if (index == 0) index = FT_Get_Char_Index(f, '?');
    Glyph g;
    // Hinted for monochrome output and rendered to one bit per pixel.
    if (FT_Load_Glyph(f, index, FT_LOAD_TARGET_MONO | FT_LOAD_RENDER | FT_LOAD_MONOCHROME | FT_LOAD_NO_BITMAP) != 0)
      return g;
    const FT_GlyphSlot slot = f->glyph;
    const FT_Bitmap& b = slot->bitmap;
    g.left = slot->bitmap_left;
    g.top = slot->bitmap_top;
    g.advance = static_cast<int>((slot->advance.x + 32) >> 6);
    g.width = static_cast<int>(b.width);
    g.height = static_cast<int>(b.rows);
    g.bits.assign(static_cast<size_t>(g.width) * static_cast<size_t>(g.height), 0);
    for (int y = 0; y < g.height; ++y) {
      const unsigned char* row = b.buffer + static_cast<ptrdiff_t>(y) * b.pitch;
      for (int x = 0; x < g.width; ++x) {
        bool on = b.pixel_mode == FT_PIXEL_MODE_MONO ? ((row[x / 8] >> (7 - x % 8)) & 1) != 0
                                                      : row[x] >= 128;  // any other mode: threshold
        g.bits[static_cast<size_t>(y) * static_cast<size_t>(g.width) + static_cast<size_t>(x)] = on ? 1 : 0;
      }
    }
    for (int y = 0; y < g.height; ++y)
      for (int x = 0; x < g.width;) {
        if (!g.pixel(x, y)) {
          ++x;
          continue;
        }
        int start = x;
        while (x < g.width && g.pixel(x, y)) ++x;
        g.runs.push_back({static_cast<int16_t>(start), static_cast<int16_t>(y), static_cast<int16_t>(x - start)});
      }
    return g;
  }
};

FontRenderer::FontRenderer() : impl_(std::make_unique<Impl>()) {}
FontRenderer::~FontRenderer() = default;

const FontMetrics& FontRenderer::metrics(const FontKey& key) { return impl_->sized(key).metrics; }

const Glyph& FontRenderer::glyph(const FontKey& key, unsigned char ch) {
  Impl::Sized& s = impl_->sized(key);
  std::optional<Glyph>& g = s.glyphs[ch];
  if (!g) [[unlikely]] impl_->load(s, key, ch);
  return *g;
}

int FontRenderer::glyphs(const FontKey& key, std::string_view text, std::vector<const Glyph*>& out, size_t keep) {
  Impl::Sized& s = impl_->sized(key);
  out.resize(std::min(keep, text.size()));
  int width = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const auto ch = static_cast<unsigned char>(text[i]);
    std::optional<Glyph>& g = s.glyphs[ch];
    if (!g) [[unlikely]] impl_->load(s, key, ch);
    if (i < out.size()) out[i] = &*g;
    width += g->advance;
    // Past kMaxTextWidth the rest of a long string is off every screen: its width stays there.
    if (width >= kMaxTextWidth) [[unlikely]] {
      for (size_t j = i + 1; j < out.size(); ++j) out[j] = &glyph(key, static_cast<unsigned char>(text[j]));
      return kMaxTextWidth;
    }
  }
  return width;
}

int FontRenderer::width(const FontKey& key, std::string_view text) {
  std::vector<const Glyph*> none;
  return glyphs(key, text, none, 0);
}

}  // namespace rb
