#include "screen/font.h"

#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace rb {

namespace {

uint32_t le32(const unsigned char* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

/// Decodes one UTF-8 sequence; returns the code point and advances `i`.
uint32_t utf8(const unsigned char* p, size_t size, size_t& i) {
  unsigned char c = p[i++];
  if (c < 0x80) return c;
  int extra = c >= 0xf0 ? 3 : c >= 0xe0 ? 2 : 1;
  uint32_t cp = c & (0x3f >> extra);
  for (int k = 0; k < extra && i < size; ++k) cp = (cp << 6) | (p[i++] & 0x3f);
  return cp;
}

}  // namespace

BitmapFont::BitmapFont(const unsigned char* data, size_t size, bool bold) : bold_(bold) {
  size_t glyphCount = 0, headerSize = 0;
  bool unicode = false, psf2 = false;
  if (size >= 4 && data[0] == 0x36 && data[1] == 0x04) {
    unsigned mode = data[2];
    glyphCount = (mode & 1) ? 512 : 256;
    unicode = (mode & 2) != 0;
    bytesPerGlyph_ = height_ = data[3];
    width_ = 8;
    headerSize = 4;
  } else if (size >= 32 && le32(data) == 0x864ab572u) {
    psf2 = true;
    headerSize = le32(data + 8);
    unicode = (le32(data + 12) & 1) != 0;
    glyphCount = le32(data + 16);
    bytesPerGlyph_ = static_cast<int>(le32(data + 20));
    height_ = static_cast<int>(le32(data + 24));
    width_ = static_cast<int>(le32(data + 28));
  } else {
    throw std::runtime_error("embedded font is not a PSF font");
  }
  rowBytes_ = (width_ + 7) / 8;
  size_t glyphBytes = glyphCount * static_cast<size_t>(bytesPerGlyph_);
  if (headerSize + glyphBytes > size) throw std::runtime_error("embedded font is truncated");
  glyphs_.assign(data + headerSize, data + headerSize + glyphBytes);

  // Latin-1 code -> glyph. Without a table, glyph n draws character n.
  for (int c = 0; c < 256; ++c) map_[c] = static_cast<uint16_t>(c < static_cast<int>(glyphCount) ? c : 0);
  if (!unicode) return;
  bool found[256] = {};
  size_t i = headerSize + glyphBytes;
  for (size_t glyph = 0; glyph < glyphCount && i < size; ++glyph) {
    bool inSequence = false;
    if (!psf2) {
      while (i + 1 < size) {
        uint32_t v = uint32_t(data[i]) | uint32_t(data[i + 1]) << 8;
        i += 2;
        if (v == 0xffff) break;
        if (v == 0xfffe) inSequence = true;
        else if (!inSequence && v < 256 && !found[v]) {
          map_[v] = static_cast<uint16_t>(glyph);
          found[v] = true;
        }
      }
    } else {
      while (i < size) {
        if (data[i] == 0xff) {
          ++i;
          break;
        }
        if (data[i] == 0xfe) {
          inSequence = true;
          ++i;
          continue;
        }
        uint32_t v = utf8(data, size, i);
        if (!inSequence && v < 256 && !found[v]) {
          map_[v] = static_cast<uint16_t>(glyph);
          found[v] = true;
        }
      }
    }
  }
  // Characters the font lacks are drawn as '?'.
  for (int c = 0; c < 256; ++c)
    if (!found[c]) map_[c] = found['?'] ? map_['?'] : 0;
}

namespace {

struct FontSet {
  std::vector<std::unique_ptr<BitmapFont>> regular, bold;
  std::unique_ptr<BitmapFont> console;
};

const FontSet& fonts() {
  static const FontSet set = [] {
    FontSet s;
    for (size_t i = 0; i < fontdata::kFontCount; ++i) {
      const auto& f = fontdata::kFonts[i];
      auto font = std::make_unique<BitmapFont>(f.data, f.size, f.bold != 0);
      if (std::strcmp(f.name, "vga16") == 0) s.console = std::move(font);
      else (f.bold ? s.bold : s.regular).push_back(std::move(font));
    }
    return s;
  }();
  return set;
}

}  // namespace

const BitmapFont& consoleFont() { return *fonts().console; }

const BitmapFont& textFont(int pixelHeight, bool bold) {
  const auto& list = bold ? fonts().bold : fonts().regular;
  const BitmapFont* best = list.front().get();
  for (const auto& f : list)
    if (f->height() <= pixelHeight && f->height() >= best->height()) best = f.get();
  return *best;
}

}  // namespace rb
