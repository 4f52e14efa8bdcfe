#include "base/text.h"

#include <cstdio>

namespace rb {

std::string cQuoted(std::string_view s, size_t maxChars, char quote) {
  std::string out(1, quote);
  size_t n = 0;
  for (char c : s) {
    if (n++ == maxChars) {
      out += "...";
      break;
    }
    if (c == quote) {
      out += '\\';
      out += c;
      continue;
    }
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 32 || c == 0x7F) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + quote;
}

}  // namespace rb
