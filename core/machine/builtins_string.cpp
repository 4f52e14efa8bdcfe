// String and conversion built-ins. Positions are 1-based (mid, instr, extract), as in BASIC.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "machine/builtins_impl.h"
#include "base/runtime_error.h"
#include "base/text.h"

namespace rb::builtins {

namespace {
size_t clampCount(int64_t n, size_t size) {
  if (n <= 0) return 0;
  return static_cast<size_t>(std::min<int64_t>(n, static_cast<int64_t>(size)));
}
}  // namespace

Value strLength(Machine&, Args& a) { return Value::integer(static_cast<int64_t>(a.str(0).size())); }

Value strLeft(Machine&, Args& a) {
  const std::string& s = a.str(0);
  return Value::string(s.substr(0, clampCount(a.integer(1), s.size())));
}

Value strRight(Machine&, Args& a) {
  const std::string& s = a.str(0);
  size_t n = clampCount(a.integer(1), s.size());
  return Value::string(s.substr(s.size() - n));
}

Value strMid(Machine&, Args& a) {
  const std::string& s = a.str(0);
  int64_t start = a.integer(1);
  if (start < 1) throw RuntimeError(a.describe(1) + " must be 1 or more (1 is the first character)");
  if (static_cast<uint64_t>(start) > s.size()) return Value::string("");
  size_t from = static_cast<size_t>(start - 1);
  size_t count = a.has(2) ? clampCount(a.integer(2), s.size() - from) : s.size() - from;
  return Value::string(s.substr(from, count));
}

Value strUpper(Machine&, Args& a) {
  std::string s = a.str(0);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return Value::string(std::move(s));
}

Value strLower(Machine&, Args& a) {
  std::string s = a.str(0);
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return Value::string(std::move(s));
}

namespace {
std::string trimmed(const std::string& s, bool left, bool right) {
  size_t b = 0, e = s.size();
  if (left)
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  if (right)
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}
}  // namespace

Value strTrim(Machine&, Args& a) { return Value::string(trimmed(a.str(0), true, true)); }
Value strTrimL(Machine&, Args& a) { return Value::string(trimmed(a.str(0), true, false)); }
Value strTrimR(Machine&, Args& a) { return Value::string(trimmed(a.str(0), false, true)); }

Value strSpaces(Machine&, Args& a) {
  int64_t n = a.integer(0);
  if (n > kMaxString) throw RuntimeError("spaces(): string too long");
  return Value::string(std::string(static_cast<size_t>(std::max<int64_t>(n, 0)), ' '));
}

Value strReverse(Machine&, Args& a) {
  std::string s = a.str(0);
  std::reverse(s.begin(), s.end());
  return Value::string(std::move(s));
}

/// The first place at or after `from` where `needle` occurs in `hay`, or npos. Short needles
/// use the library's search; long ones the Knuth-Morris-Pratt scan, linear in both lengths, so
/// that no pair of strings (a long run of one letter and the same run plus one other) makes a
/// search quadratic. Its table (4 bytes a character of the needle) is counted against
/// --max-memory before it is made.
size_t findText(Machine& machine, const std::string& hay, const std::string& needle, size_t from) {
  constexpr size_t kShortNeedle = 64;
  if (needle.size() < kShortNeedle || from >= hay.size()) return hay.find(needle, from);
  if (hay.size() - from < needle.size()) return std::string::npos;
  size_t m = needle.size();
  if (uint64_t table = m * sizeof(uint32_t); !machine.memoryFits(table))
    machine.reserveMemory(table, "searching for a string of " + std::to_string(m) + " characters");
  // border[i]: the length of the longest proper border of needle[0..i].
  std::vector<uint32_t> border(m, 0);
  for (size_t i = 1, k = 0; i < m; ++i) {
    while (k > 0 && needle[i] != needle[k]) k = border[k - 1];
    if (needle[i] == needle[k]) ++k;
    border[i] = static_cast<uint32_t>(k);
  }
  for (size_t i = from, k = 0; i < hay.size(); ++i) {
    while (k > 0 && hay[i] != needle[k]) k = border[k - 1];
    if (hay[i] == needle[k]) ++k;
    if (k == m) return i + 1 - m;
  }
  return std::string::npos;
}

Value strInstr(Machine& m, Args& a) {
  const std::string& s = a.str(0);
  const std::string& f = a.str(1);
  int64_t start = a.intOr(2, 1);
  if (start < 1) start = 1;
  if (static_cast<uint64_t>(start) > s.size() + 1) return Value::integer(0);
  size_t at = findText(m, s, f, static_cast<size_t>(start - 1));
  return Value::integer(at == std::string::npos ? 0 : static_cast<int64_t>(at) + 1);
}

Value strContains(Machine& m, Args& a) {
  return Value::boolean(findText(m, a.str(0), a.str(1), 0) != std::string::npos);
}

Value strReplace(Machine& m, Args& a) {
  const std::string& s = a.str(0);
  const std::string& f = a.str(1);
  const std::string& w = a.str(2);
  if (f.empty()) return a[0];
  std::string out;
  size_t pos = 0;
  for (uint32_t found = 1;; ++found) {
    size_t at = findText(m, s, f, pos);
    if (at == std::string::npos) break;
    if (found % 65536 == 0) m.checkAlarms();  // millions of matches: the time limit still holds
    out.append(s, pos, at - pos);
    out += w;
    if (static_cast<int64_t>(out.size()) > kMaxString) throw RuntimeError("replace(): string too long");
    pos = at + f.size();
  }
  out.append(s, pos, std::string::npos);
  return Value::string(std::move(out));
}

Value strExtract(Machine& m, Args& a) {
  const std::string& s = a.str(0);
  const std::string& d = a.str(1);
  int64_t n = a.integer(2);
  if (d.empty()) throw RuntimeError(a.describe(1) + " must not be empty");
  if (n < 1) return Value::string("");
  std::string_view found;  // "" when s has fewer than n fields
  int64_t field = 0;
  forEachField(m, s, d, [&](std::string_view f) {
    if (++field < n) return true;
    found = f;
    return false;
  });
  return Value::string(std::string(found));
}

Value strChar(Machine&, Args& a) {
  int64_t c = a.integer(0);
  if (c < 0 || c > 255) throw RuntimeError(a.describe(0) + " must be a character code 0..255, got " + std::to_string(c));
  return Value::string(std::string(1, static_cast<char>(c)));
}

Value strAscii(Machine&, Args& a) {
  const std::string& s = a.str(0);
  if (s.empty()) return Value::integer(0);
  return Value::integer(static_cast<unsigned char>(s[0]));
}

Value strToString(Machine&, Args& a) {
  if (a[0].isStr()) return a[0];
  if (a.has(1)) {
    int64_t decimals = std::clamp<int64_t>(a.integer(1), 0, 15);
    // The largest finite number has 309 digits before the point: room for them all.
    char buf[400];
    std::snprintf(buf, sizeof buf, "%.*f", static_cast<int>(decimals), a.num(0));
    return Value::string(buf);
  }
  (void)a.num(0);
  return Value::string(formatValue(a[0]));
}

Value strToNumber(Machine&, Args& a) {
  if (a[0].isNumeric()) return a[0];
  Value v;
  if (parseNumber(a.str(0), v)) return v;
  if (a.has(1)) return a[1];
  throw RuntimeError("toNumber(): " + cQuoted(a.str(0)) + " is not a number");
}

Value strIsNumber(Machine&, Args& a) { return Value::boolean(a[0].isNumeric()); }
Value strIsString(Machine&, Args& a) { return Value::boolean(a[0].isStr()); }

}  // namespace rb::builtins
