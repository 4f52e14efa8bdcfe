#include "base/number.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace rb {

std::size_t formatNumberTo(double d, char* out) {
  const char* word = d == 0 ? "0"  // also turns -0 into 0
                     : std::isnan(d) ? "nan"
                     : std::isinf(d) ? (d > 0 ? "inf" : "-inf")
                                     : nullptr;
  if (word) {
    std::size_t n = std::strlen(word);
    std::memcpy(out, word, n);
    return n;
  }
  // %.15g of a double is at most 22 characters ("-1.23456789012345e-308").
  int n = std::snprintf(out, kNumberTextSize, "%.15g", d);
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

std::string formatNumber(double d) {
  char buf[kNumberTextSize];
  return std::string(buf, formatNumberTo(d, buf));
}

}  // namespace rb
