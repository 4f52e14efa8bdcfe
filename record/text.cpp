#include "text.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rb::record {

namespace {

/// The length of the well-formed UTF-8 sequence at s[i] and its code point in `cp`, or 0 when
/// the byte there begins none (a cut, overlong or surrogate sequence, a stray byte).
size_t decodeUtf8(std::string_view s, size_t i, uint32_t& cp) {
  unsigned char c = static_cast<unsigned char>(s[i]);
  size_t len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
  if (len == 0 || i + len > s.size()) return 0;
  cp = len == 1 ? c : len == 2 ? c & 0x1F : len == 3 ? c & 0x0F : c & 0x07;
  for (size_t k = 1; k < len; ++k) {
    unsigned char d = static_cast<unsigned char>(s[i + k]);
    if ((d & 0xC0) != 0x80) return 0;
    cp = cp << 6 | (d & 0x3F);
  }
  static const uint32_t minimum[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < minimum[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return len;
}

/// A Latin-1 byte as UTF-8.
void appendLatin1(std::string& out, unsigned char c) {
  out += static_cast<char>(0xC0 | c >> 6);
  out += static_cast<char>(0x80 | (c & 0x3F));
}

void appendHex(std::string& out, const char* prefix, uint32_t value, int digits) {
  static const char kHex[] = "0123456789abcdef";
  out += prefix;
  for (int d = digits - 1; d >= 0; --d) out += kHex[(value >> (4 * d)) & 0xF];
}

bool bidiOrSeparator(uint32_t cp) {
  return cp == 0x061C || cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) ||
         (cp >= 0x2066 && cp <= 0x2069) || cp == 0x2028 || cp == 0x2029;
}

/// The length of the blank at s[i] that GitHub's runner trims before it looks for `::` (.NET's
/// char.IsWhiteSpace, less what shownText has escaped already), with the zero-width ones too;
/// 0 when there is none.
size_t blankAt(std::string_view s, size_t i) {
  if (s[i] == ' ' || s[i] == '\t') return 1;
  uint32_t cp = 0;
  size_t len = decodeUtf8(s, i, cp);
  bool blank = cp == 0xA0 || cp == 0x1680 || cp == 0x180E || (cp >= 0x2000 && cp <= 0x200B) || cp == 0x202F ||
               cp == 0x205F || cp == 0x3000 || cp == 0xFEFF;
  return len > 1 && blank ? len : 0;
}

/// Workflow commands made inert: a line (of valid UTF-8 without CR) that begins with `::`
/// after blanks gets `\x3a` for its first colon, and every `##[` becomes `\x23#[`. Where a
/// character became four, its place in `s` goes into `grown`.
std::string withoutCommands(const std::string& s, std::vector<size_t>& grown) {
  std::string out;
  out.reserve(s.size());
  bool lineStart = true;
  for (size_t i = 0; i < s.size();) {
    if (lineStart) {
      size_t blank = blankAt(s, i);
      if (blank) {
        out.append(s, i, blank);
        i += blank;
        continue;
      }
      lineStart = false;
      if (s.compare(i, 2, "::") == 0) {
        out += "\\x3a";
        grown.push_back(i++);
        continue;
      }
    }
    if (s.compare(i, 3, "##[") == 0) {
      out += "\\x23";
      grown.push_back(i++);
      continue;
    }
    if (s[i] == '\n') lineStart = true;
    out += s[i++];
  }
  return out;
}

}  // namespace

std::string toUtf8(std::string_view s, bool xmlSafe) {
  static const std::string kReplacement = "\xEF\xBF\xBD";
  std::string out;
  size_t i = 0;
  while (i < s.size()) {
    uint32_t cp = 0;
    size_t len = decodeUtf8(s, i, cp);
    if (len == 0) {  // not UTF-8: a byte of a Windows program's Latin-1 text
      appendLatin1(out, static_cast<unsigned char>(s[i]));
      ++i;
      continue;
    }
    bool allowed = !xmlSafe || (cp >= 0x20 ? cp != 0xFFFE && cp != 0xFFFF : (cp == 0x9 || cp == 0xA || cp == 0xD));
    if (allowed) out.append(s, i, len);
    else out += kReplacement;
    i += len;
  }
  return out;
}

std::string shownText(std::string_view s, TextShape shape, std::vector<size_t>* offsets) {
  bool block = shape == TextShape::Block;
  std::string out;
  out.reserve(s.size());
  std::vector<size_t> place;  // with offsets: place[i] is where s[i] begins in `out`
  if (offsets) place.reserve(s.size() + 1);
  for (size_t i = 0; i < s.size();) {
    uint32_t cp = 0;
    size_t len = decodeUtf8(s, i, cp);
    if (offsets) place.insert(place.end(), len ? len : 1, out.size());
    if (len == 0) {  // not UTF-8: Latin-1, whose C1 range are controls
      unsigned char c = static_cast<unsigned char>(s[i++]);
      if (c < 0xA0) appendHex(out, "\\x", c, 2);
      else appendLatin1(out, c);
      continue;
    }
    if (cp == '\n') out += block ? "\n" : "\\n";
    else if (cp == '\t') out += block ? "\t" : "\\t";
    else if (cp == '\r') out += block ? "^M" : "\\r";
    else if (cp < 0x20) {
      out += '^';
      out += static_cast<char>('@' + cp);
    } else if (cp == 0x7F) out += "^?";
    else if (cp >= 0x80 && cp <= 0x9F) appendHex(out, "\\x", cp, 2);
    else if (bidiOrSeparator(cp)) appendHex(out, "\\u", cp, 4);
    else out.append(s, i, len);
    i += len;
  }
  std::vector<size_t> grown;
  std::string shown = withoutCommands(out, grown);
  if (offsets) {
    place.push_back(out.size());
    for (size_t& o : *offsets) {
      size_t at = place[std::min(o, s.size())];
      o = at + 3 * static_cast<size_t>(std::lower_bound(grown.begin(), grown.end(), at) - grown.begin());
    }
  }
  return shown;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csvTextField(std::string_view text) {
  std::string shown = shownText(text, TextShape::Line);
  if (shown.empty() || std::string_view("=+-@\t\r").find(shown[0]) == std::string_view::npos) return csvField(shown);
  std::string quoted(1, '\'');
  quoted += shown;
  return csvField(quoted);
}

}  // namespace rb::record
