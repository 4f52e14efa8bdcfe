#pragma once
// Included before every source of the wasm build (web/CMakeLists.txt): the libc++ of Debian's
// emscripten (LLVM 14) has std::from_chars and std::to_chars for integers only. This gives the
// double overloads the core and the SVG writer use: from_chars with its rules (C locale, no
// leading space or '+', no hex in the general format), on strtod, and to_chars with a format
// and a precision, on snprintf (musl's is correctly rounded, as to_chars is; the page never
// changes the C locale). The native build never sees it.
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

namespace std {
inline from_chars_result from_chars(const char* first, const char* last, double& value) {
  if (first == last || *first == '+' || *first == ' ' || *first == '\t' || *first == '\n')
    return {first, errc::invalid_argument};
  std::string text(first, last);
  const char* digits = text.c_str() + (text[0] == '-' ? 1 : 0);
  if (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
    text.resize(static_cast<size_t>(digits - text.c_str()) + 1);  // "0x1": the 0 alone
  }
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str()) return {first, errc::invalid_argument};
  const char* stop = first + (end - text.c_str());
  if (errno == ERANGE) return {stop, errc::result_out_of_range};
  value = v;
  return {stop, errc{}};
}

inline to_chars_result to_chars(char* first, char* last, double value, chars_format format, int precision) {
  const char* spec = format == chars_format::fixed ? "%.*f" : format == chars_format::scientific ? "%.*e" : "%.*g";
  int n = std::snprintf(first, static_cast<size_t>(last - first), spec, precision, value);
  if (n < 0 || n >= last - first) return {last, errc::value_too_large};
  return {first + n, errc{}};
}
}  // namespace std
