#include "base/source.h"

#include <cstring>

#include "base/large_memory.h"

namespace rb {

SourceFile::SourceFile(std::string name, std::string text, SourceLoc includedFrom)
    : name_(std::move(name)), text_(std::move(text)), includedFrom_(includedFrom) {
  // Counted first, so that the table has exactly its size (a big file has millions of lines).
  const char* begin = text_.data();
  const char* end = begin + text_.size();
  size_t lines = 1;
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', size_t(end - p)))); ++p)
    ++lines;
  lineStarts_.reserve(lines);
  prepareLarge(lineStarts_.data(), lines * sizeof(uint32_t));
  lineStarts_.push_back(0);
  for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', size_t(end - p)))); ++p) {
    if (p + 1 < end) lineStarts_.push_back(static_cast<uint32_t>(p + 1 - begin));
  }
}

std::string_view SourceFile::lineText(uint32_t line) const {
  if (line == 0 || line > lineStarts_.size()) return {};
  size_t begin = lineStarts_[line - 1];
  size_t end = line < lineStarts_.size() ? lineStarts_[line] : text_.size();
  std::string_view s(text_.data() + begin, end - begin);
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

uint32_t SourceSet::add(std::string name, std::string text, SourceLoc includedFrom) {
  files_.push_back(std::make_unique<SourceFile>(std::move(name), std::move(text), includedFrom));
  return static_cast<uint32_t>(files_.size() - 1);
}

}  // namespace rb

namespace rb {

namespace {

/// Length of the valid UTF-8 sequence at s[i], or 0 when it is not one.
size_t utf8Length(std::string_view s, size_t i) {
  auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  unsigned char c = byte(i);
  if (c < 0x80) return 1;
  size_t n;
  uint32_t cp;
  if ((c & 0xE0) == 0xC0) { n = 2; cp = c & 0x1F; }
  else if ((c & 0xF0) == 0xE0) { n = 3; cp = c & 0x0F; }
  else if ((c & 0xF8) == 0xF0) { n = 4; cp = c & 0x07; }
  else return 0;
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  static const uint32_t kMin[] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kMin[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

void appendUtf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

/// Windows-1252's characters for 0x80..0x9F (0: undefined there).
constexpr uint16_t kCp1252High[32] = {
    0x20AC, 0, 0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160, 0x2039,
    0x0152, 0, 0x017D, 0, 0, 0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,
    0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0, 0x017E, 0x0178};

bool oddControl(unsigned char c) {
  return c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v' && c != 0x1A;
}

}  // namespace

DecodedText decodeSourceText(std::string raw) {
  DecodedText out;
  size_t start = 0;
  if (raw.compare(0, 3, "\xEF\xBB\xBF") == 0) {
    out.hadBom = true;
    start = 3;
  }
  size_t nul = raw.find('\0', start);
  if (nul != std::string::npos) {
    out.kind = DecodedText::Binary;
    out.why = "a NUL byte at byte " + std::to_string(nul + 1);
    return out;
  }
  bool utf8 = true;
  size_t odd = 0;
  const char* bytes = raw.data();
  for (size_t i = start; i < raw.size();) {
    // Most of a program is printable ASCII: eight bytes at a time while no byte is below 0x20
    // or above 0x7f.
    while (i + 8 <= raw.size()) {
      uint64_t w;
      std::memcpy(&w, bytes + i, 8);
      constexpr uint64_t kHigh = 0x8080808080808080ull;
      if (((w | (w - 0x2020202020202020ull)) & kHigh) != 0) break;
      i += 8;
    }
    if (i >= raw.size()) break;
    unsigned char c = static_cast<unsigned char>(bytes[i]);
    if (c >= 0x20 && c < 0x80) {
      ++i;
      continue;
    }
    if (oddControl(c)) ++odd;
    size_t n = utf8Length(raw, i);
    if (n == 0) {
      utf8 = false;
      break;
    }
    i += n;
  }
  size_t body = raw.size() - start;
  if (utf8) {
    if (odd * 100 > body) {
      out.kind = DecodedText::Binary;
      out.why = std::to_string(odd) + " control characters";
      return out;
    }
    raw.erase(0, start);
    out.text = std::move(raw);
    return out;
  }
  // Not UTF-8: Windows-1252, one character a byte.
  out.kind = DecodedText::Windows1252;
  odd = 0;
  out.text.reserve(body + body / 8);
  for (size_t i = start; i < raw.size(); ++i) {
    unsigned char c = static_cast<unsigned char>(raw[i]);
    if (c < 0x80) {
      if (oddControl(c)) ++odd;
      out.text += static_cast<char>(c);
    } else if (c < 0xA0) {
      uint16_t cp = kCp1252High[c - 0x80];
      if (cp == 0) {
        ++odd;
        cp = 0xFFFD;
      }
      appendUtf8(out.text, cp);
    } else {
      appendUtf8(out.text, c);
    }
  }
  if (odd * 100 > body) {
    out.kind = DecodedText::Binary;
    out.why = "bytes that are neither UTF-8 nor Windows-1252 text";
    out.text.clear();
  }
  return out;
}

}  // namespace rb
