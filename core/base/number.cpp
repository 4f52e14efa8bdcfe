#include "base/number.h"

#include <cmath>
#include <cstdio>

namespace rb {

std::string formatNumber(double d) {
  if (d == 0) return "0";  // also turns -0 into 0
  if (std::isnan(d)) return "nan";
  if (std::isinf(d)) return d > 0 ? "inf" : "-inf";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", d);
  return buf;
}

}  // namespace rb
