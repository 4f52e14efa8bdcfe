// Math built-ins: abs() .. random(). Angles are in radians, as in RobotBASIC.
#include <cmath>
#include <numbers>

#include "machine/builtins_impl.h"
#include "base/checked_math.h"
#include "base/runtime_error.h"

namespace rb::builtins {

Value numberResult(double d) {
  if (std::isnan(d)) throw RuntimeError("the result is not a number");
  if (std::isinf(d)) throw RuntimeError("the result is too large");
  return Value::number(d);
}

namespace {
Value integral(double d) {
  if (std::isnan(d) || std::isinf(d)) return numberResult(d);
  if (d >= -9.2e18 && d <= 9.2e18) return Value::integer(static_cast<int64_t>(d));
  return Value::number(d);
}
void domain(bool ok, Args& a, const char* what) {
  if (!ok) throw RuntimeError(std::string(a.builtin().name) + "(): " + what);
}
}  // namespace

Value mathAbs(Machine&, Args& a) {
  if (a[0].isInt() && a[0].i() != INT64_MIN) return Value::integer(a[0].i() < 0 ? -a[0].i() : a[0].i());
  return Value::number(std::fabs(a.num(0)));
}
Value mathSqrt(Machine&, Args& a) {
  double x = a.num(0);
  domain(x >= 0, a, "the square root of a negative number is not defined");
  return numberResult(std::sqrt(x));
}
Value mathSin(Machine&, Args& a) { return numberResult(std::sin(a.num(0))); }
Value mathCos(Machine&, Args& a) { return numberResult(std::cos(a.num(0))); }
Value mathTan(Machine&, Args& a) { return numberResult(std::tan(a.num(0))); }
Value mathAsin(Machine&, Args& a) {
  double x = a.num(0);
  domain(x >= -1 && x <= 1, a, "the argument must be between -1 and 1");
  return numberResult(std::asin(x));
}
Value mathAcos(Machine&, Args& a) {
  double x = a.num(0);
  domain(x >= -1 && x <= 1, a, "the argument must be between -1 and 1");
  return numberResult(std::acos(x));
}
Value mathAtan(Machine&, Args& a) { return numberResult(std::atan(a.num(0))); }
Value mathAtan2(Machine&, Args& a) { return numberResult(std::atan2(a.num(0), a.num(1))); }
Value mathExp(Machine&, Args& a) { return numberResult(std::exp(a.num(0))); }
Value mathLn(Machine&, Args& a) {
  double x = a.num(0);
  domain(x > 0, a, "the logarithm is only defined for numbers above 0");
  return numberResult(std::log(x));
}
Value mathLog(Machine&, Args& a) {
  double x = a.num(0);
  domain(x > 0, a, "the logarithm is only defined for numbers above 0");
  return numberResult(std::log10(x));
}
Value mathPow(Machine&, Args& a) {
  if (a[0].isInt() && a[1].isInt() && a[1].i() >= 0 && a[1].i() < 64) {
    int64_t r = 1;
    bool overflow = false;
    for (int64_t i = 0; i < a[1].i() && !overflow; ++i) overflow = mulOverflows(r, a[0].i(), &r);
    if (!overflow) return Value::integer(r);
  }
  return numberResult(std::pow(a.num(0), a.num(1)));
}
Value mathInt(Machine&, Args& a) { return a[0].isInt() ? a[0] : integral(std::trunc(a.num(0))); }
Value mathFloor(Machine&, Args& a) { return a[0].isInt() ? a[0] : integral(std::floor(a.num(0))); }
Value mathCeil(Machine&, Args& a) { return a[0].isInt() ? a[0] : integral(std::ceil(a.num(0))); }
Value mathFrac(Machine&, Args& a) {
  if (a[0].isInt()) return Value::integer(0);
  double x = a.num(0);
  return Value::number(x - std::trunc(x));
}
Value mathRound(Machine&, Args& a) { return a[0].isInt() ? a[0] : integral(std::round(a.num(0))); }
Value mathSign(Machine&, Args& a) {
  double x = a.num(0);
  return Value::integer(x > 0 ? 1 : x < 0 ? -1 : 0);
}
Value mathMin(Machine&, Args& a) {
  int best = 0;
  for (int i = 1; i < a.size(); ++i)
    if (a.num(i) < a.num(best)) best = i;
  (void)a.num(0);
  return a[best];
}
Value mathMax(Machine&, Args& a) {
  int best = 0;
  for (int i = 1; i < a.size(); ++i)
    if (a.num(i) > a.num(best)) best = i;
  (void)a.num(0);
  return a[best];
}
Value mathLimit(Machine&, Args& a) {
  double x = a.num(0), lo = a.num(1), hi = a.num(2);
  if (x < lo) return a[1];
  if (x > hi) return a[2];
  return a[0];
}
Value mathWithin(Machine&, Args& a) {
  double x = a.num(0);
  return Value::boolean(x >= a.num(1) && x <= a.num(2));
}
Value mathPi(Machine&, Args& a) { return Value::number(std::numbers::pi * a.numOr(0, 1.0)); }
Value mathRtoD(Machine&, Args& a) { return numberResult(a.num(0) * (180.0 / std::numbers::pi)); }
Value mathDtoR(Machine&, Args& a) { return numberResult(a.num(0) * (std::numbers::pi / 180.0)); }
Value mathPolarA(Machine&, Args& a) { return numberResult(std::atan2(a.num(1), a.num(0))); }
Value mathPolarR(Machine&, Args& a) { return numberResult(std::hypot(a.num(0), a.num(1))); }
Value mathCartX(Machine&, Args& a) { return numberResult(a.num(0) * std::cos(a.num(1))); }
Value mathCartY(Machine&, Args& a) { return numberResult(a.num(0) * std::sin(a.num(1))); }
Value mathRandom(Machine& m, Args& a) {
  int64_t n = a.integer(0);
  if (n < 1) throw RuntimeError("random(n) needs n >= 1, got " + std::to_string(n));
  return Value::integer(static_cast<int64_t>(m.rng().below(static_cast<uint64_t>(n))));
}
Value mathRRandom(Machine& m, Args& a) { return Value::number(m.rng().unit() * a.num(0)); }
Value mathRandomize(Machine& m, Args& a) {
  m.rng().reseed(static_cast<uint64_t>(a.integer(0)));
  return {};
}

}  // namespace rb::builtins
