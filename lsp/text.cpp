#include "text.h"

#include <cctype>
#include <filesystem>

namespace rb::lsp {

namespace {

/// Length in bytes of the UTF-8 sequence starting at s[i] (1 for an invalid byte, which then
/// counts as one character: a Latin-1 file read as bytes).
size_t utf8Length(std::string_view s, size_t i, uint32_t* units16) {
  auto b = static_cast<unsigned char>(s[i]);
  size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
  if (n == 0 || i + n > s.size()) {
    *units16 = 1;
    return 1;
  }
  for (size_t k = 1; k < n; ++k) {
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) {
      *units16 = 1;
      return 1;
    }
  }
  *units16 = n == 4 ? 2 : 1;
  return n;
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

uint32_t toLspCharacter(std::string_view line, size_t byteCol, Encoding enc) {
  if (byteCol > line.size()) byteCol = line.size();
  if (enc == Encoding::Utf8) return static_cast<uint32_t>(byteCol);
  uint32_t units = 0;
  size_t i = 0;
  while (i < byteCol) {
    uint32_t u = 1;
    i += utf8Length(line, i, &u);
    units += u;
  }
  return units;
}

size_t toByteColumn(std::string_view line, uint32_t character, Encoding enc) {
  if (enc == Encoding::Utf8) return character < line.size() ? character : line.size();
  uint32_t units = 0;
  size_t i = 0;
  while (i < line.size() && units < character) {
    uint32_t u = 1;
    i += utf8Length(line, i, &u);
    units += u;
  }
  return i;
}

std::string_view lineOf(std::string_view text, uint32_t line) {
  size_t start = 0;
  for (uint32_t l = 0; l < line; ++l) {
    size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) return {};
    start = nl + 1;
  }
  size_t end = text.find('\n', start);
  if (end == std::string_view::npos) end = text.size();
  std::string_view s = text.substr(start, end - start);
  if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
  return s;
}

std::string uriToPath(std::string_view uri) {
  constexpr std::string_view kFile = "file://";
  if (uri.substr(0, kFile.size()) != kFile) return std::string(uri);
  std::string_view rest = uri.substr(kFile.size());
  // Skip an authority ("file://localhost/x"): the path starts at the first '/'.
  size_t slash = rest.find('/');
  rest = slash == std::string_view::npos ? std::string_view{} : rest.substr(slash);
  std::string out;
  for (size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] == '%' && i + 2 < rest.size() && hexValue(rest[i + 1]) >= 0 &&
        hexValue(rest[i + 2]) >= 0) {
      out.push_back(static_cast<char>(hexValue(rest[i + 1]) * 16 + hexValue(rest[i + 2])));
      i += 2;
    } else {
      out.push_back(rest[i]);
    }
  }
  return out;
}

std::string pathToUri(std::string_view path) {
  std::string p(path);
  std::error_code ec;
  if (!p.empty() && p.front() != '/') {
    std::filesystem::path abs = std::filesystem::absolute(p, ec);
    if (!ec) p = abs.lexically_normal().string();
  }
  static const char* hex = "0123456789ABCDEF";
  std::string out = "file://";
  for (char c : p) {
    auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
      out.push_back(c);
    } else {
      out.push_back('%');
      out.push_back(hex[u >> 4]);
      out.push_back(hex[u & 15]);
    }
  }
  return out;
}

bool isNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '$';
}

Span nameAt(std::string_view line, size_t col) {
  if (col > line.size()) col = line.size();
  size_t b = col;
  while (b > 0 && isNameChar(line[b - 1])) --b;
  size_t e = col;
  while (e < line.size() && isNameChar(line[e])) ++e;
  // A name starts with a letter or '_': skip leading digits ("2x" is a number, then x).
  while (b < e && std::isdigit(static_cast<unsigned char>(line[b]))) ++b;
  if (b >= e) return {col, col};
  return {b, e};
}

}  // namespace rb::lsp
