#include "base/columns.h"

#include <algorithm>
#include <iterator>

namespace rb {

namespace {

struct Range {
  char32_t first, last;
};

// Unicode's East Asian Width W and F blocks (EastAsianWidth.txt), with the emoji presentation
// blocks, coarsened to blocks: what gcc's and glibc's tables make two columns wide.
constexpr Range kWide[] = {
    {0x1100, 0x115F},   {0x231A, 0x231B},   {0x2329, 0x232A},   {0x23E9, 0x23EC},
    {0x23F0, 0x23F0},   {0x23F3, 0x23F3},   {0x25FD, 0x25FE},   {0x2614, 0x2615},
    {0x2648, 0x2653},   {0x267F, 0x267F},   {0x2693, 0x2693},   {0x26A1, 0x26A1},
    {0x26AA, 0x26AB},   {0x26BD, 0x26BE},   {0x26C4, 0x26C5},   {0x26CE, 0x26CE},
    {0x26D4, 0x26D4},   {0x26EA, 0x26EA},   {0x26F2, 0x26F3},   {0x26F5, 0x26F5},
    {0x26FA, 0x26FA},   {0x26FD, 0x26FD},   {0x2705, 0x2705},   {0x270A, 0x270B},
    {0x2728, 0x2728},   {0x274C, 0x274C},   {0x274E, 0x274E},   {0x2753, 0x2755},
    {0x2757, 0x2757},   {0x2795, 0x2797},   {0x27B0, 0x27B0},   {0x27BF, 0x27BF},
    {0x2B1B, 0x2B1C},   {0x2B50, 0x2B50},   {0x2B55, 0x2B55},   {0x2E80, 0x303E},
    {0x3041, 0x33FF},   {0x3400, 0x4DBF},   {0x4E00, 0x9FFF},   {0xA000, 0xA4CF},
    {0xA960, 0xA97F},   {0xAC00, 0xD7A3},   {0xF900, 0xFAFF},   {0xFE10, 0xFE19},
    {0xFE30, 0xFE6F},   {0xFF00, 0xFF60},   {0xFFE0, 0xFFE6},   {0x16FE0, 0x16FE4},
    {0x17000, 0x18CFF}, {0x1B000, 0x1B2FF}, {0x1F004, 0x1F004}, {0x1F0CF, 0x1F0CF},
    {0x1F18E, 0x1F18E}, {0x1F191, 0x1F19A}, {0x1F200, 0x1F251}, {0x1F300, 0x1F64F},
    {0x1F680, 0x1F6FF}, {0x1F7E0, 0x1F7EB}, {0x1F900, 0x1F9FF}, {0x1FA70, 0x1FAFF},
    {0x20000, 0x2FFFD}, {0x30000, 0x3FFFD},
};

// Combining marks (Mn, Me) of the main blocks and zero-width format characters.
constexpr Range kZero[] = {
    {0x0300, 0x036F}, {0x0483, 0x0489}, {0x0591, 0x05BD}, {0x0610, 0x061A}, {0x064B, 0x065F},
    {0x0E31, 0x0E31}, {0x0E34, 0x0E3A}, {0x0E47, 0x0E4E}, {0x1AB0, 0x1AFF}, {0x1DC0, 0x1DFF},
    {0x200B, 0x200F}, {0x2028, 0x202E}, {0x2060, 0x2064}, {0x20D0, 0x20FF}, {0x302A, 0x302D},
    {0x3099, 0x309A}, {0xFE00, 0xFE0F}, {0xFE20, 0xFE2F}, {0xFEFF, 0xFEFF}, {0xE0100, 0xE01EF},
};

template <size_t N>
bool inRanges(const Range (&table)[N], char32_t c) {
  auto it = std::upper_bound(std::begin(table), std::end(table), c,
                             [](char32_t v, const Range& r) { return v < r.first; });
  return it != std::begin(table) && c <= std::prev(it)->last;
}

/// The code point starting at byte `i` of `s` and its length in bytes (a malformed byte: itself,
/// one byte long).
char32_t decode(std::string_view s, size_t i, size_t& len) {
  auto b = static_cast<unsigned char>(s[i]);
  size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 1;
  if (n == 1 || i + n > s.size()) {
    len = 1;
    return b;
  }
  char32_t c = b & (0x7F >> n);
  for (size_t k = 1; k < n; ++k) {
    auto cont = static_cast<unsigned char>(s[i + k]);
    if ((cont & 0xC0) != 0x80) {
      len = 1;
      return b;
    }
    c = (c << 6) | (cont & 0x3F);
  }
  len = n;
  return c;
}

}  // namespace

int codePointWidth(char32_t c) {
  if (c < 0x300) return 1;
  if (inRanges(kZero, c)) return 0;
  return inRanges(kWide, c) ? 2 : 1;
}

int displayWidthAt(std::string_view s, size_t i, size_t& len) {
  char32_t c = decode(s, i, len);
  return c == '\t' ? 1 : codePointWidth(c);
}

uint32_t utf16Column(std::string_view line, uint32_t byteCol) {
  if (byteCol == 0) return 0;
  size_t target = byteCol - 1;  // 0-based byte offset
  uint32_t units = 0;
  size_t i = 0;
  while (i < line.size() && i < target) {
    size_t len = 1;
    char32_t c = decode(line, i, len);
    units += c >= 0x10000 ? 2 : 1;
    i += len;
  }
  if (target > line.size()) units += static_cast<uint32_t>(target - line.size());
  return units + 1;
}

uint32_t displayColumn(std::string_view line, uint32_t byteCol, uint32_t tabStop) {
  if (byteCol == 0) return 0;
  if (tabStop == 0) tabStop = 1;
  size_t target = byteCol - 1;
  uint32_t col = 0;  // 0-based display column
  size_t i = 0;
  while (i < line.size() && i < target) {
    size_t len = 1;
    char32_t c = decode(line, i, len);
    if (c == '\t') col += tabStop - col % tabStop;
    else col += static_cast<uint32_t>(codePointWidth(c));
    i += len;
  }
  if (target > line.size()) col += static_cast<uint32_t>(target - line.size());
  return col + 1;
}

}  // namespace rb
