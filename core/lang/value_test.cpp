#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>

#include "lang/value.h"

using namespace rb;

TEST_CASE("printedForm writes what formatValue writes, without a copy", "[value]") {
  const Value values[] = {
      Value::integer(0), Value::integer(-7), Value::integer(INT64_MAX), Value::integer(INT64_MIN),
      Value::number(0.5), Value::number(-0.0), Value::number(1e300), Value::number(-1.2345678901234567e-308),
      Value::number(0.1 + 0.2), Value::number(std::numeric_limits<double>::max()),
      Value::number(std::numeric_limits<double>::infinity()), Value::string(""), Value::string("abc"),
      Value(), Value::array({2})};
  for (const Value& v : values) {
    char room[kNumberTextSize];
    INFO(formatValue(v));
    CHECK(std::string(printedForm(v, room)) == formatValue(v));
  }
  Value s = Value::string("shared text");
  char room[kNumberTextSize];
  CHECK(printedForm(s, room).data() == s.str().data());  // a string's own text
}
