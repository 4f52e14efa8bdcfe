#include "lang/value.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace rb {

void Value::freeStr(StrObj* s) { delete s; }
void Value::freeArr(ArrObj* a) { delete a; }
__attribute__((cold, noinline)) void Value::replaceHeap(int64_t v) {
  release();
  type_ = VType::Int;
  i_ = v;
}
__attribute__((cold, noinline)) void Value::replaceHeap(double v) {
  release();
  type_ = VType::Num;
  d_ = v;
}

Value Value::string(std::string s) {
  Value r;
  r.type_ = VType::Str;
  r.s_ = new StrObj{1, std::move(s)};
  return r;
}

Value Value::array(std::vector<int64_t> dims) {
  Value r;
  r.type_ = VType::Arr;
  r.a_ = new ArrObj;
  size_t n = 1;
  for (int64_t d : dims) n *= static_cast<size_t>(d);
  r.a_->dims = std::move(dims);
  r.a_->items.resize(n, Value::integer(0));
  return r;
}

std::string_view printedForm(const Value& v, char (&room)[kNumberTextSize]) {
  switch (v.type()) {
    case VType::Int: {
      auto r = std::to_chars(room, room + kNumberTextSize, v.i());
      return {room, static_cast<std::size_t>(r.ptr - room)};
    }
    case VType::Num: return {room, formatNumberTo(v.d(), room)};
    case VType::Str: return v.str();
    case VType::Arr: return "<array>";
    case VType::Undef: return "";
  }
  return "";
}

std::string formatValue(const Value& v) {
  char room[kNumberTextSize];
  return std::string(printedForm(v, room));
}

bool parseNumber(std::string_view text, Value& out) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  if (text.empty()) return false;
  std::string_view digits = text;
  bool neg = false;
  if (digits.front() == '+' || digits.front() == '-') {
    neg = digits.front() == '-';
    digits.remove_prefix(1);
  }
  if (digits.empty()) return false;
  bool allDigits = true;
  for (char c : digits) allDigits = allDigits && std::isdigit(static_cast<unsigned char>(c));
  if (allDigits) {
    int64_t v = 0;
    auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (r.ec == std::errc() && r.ptr == digits.data() + digits.size()) {
      out = Value::integer(neg ? -v : v);
      return true;
    }
  }
  // strtod accepts "inf", "nan" and hex floats; only plain decimal forms count as numbers here.
  for (char c : digits) {
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
          c == '+' || c == '-'))
      return false;
  }
  std::string s(text);
  char* end = nullptr;
  double d = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || std::isnan(d) || std::isinf(d)) return false;
  out = Value::number(d);
  return true;
}

}  // namespace rb
