#pragma once
// Integer arithmetic that says when a result does not fit in 64 bits (rb then goes on in
// doubles, as RobotBASIC does).

#include <cstdint>

namespace rb {

/// a * b into *r; true when the product does not fit in 64 bits (as __builtin_mul_overflow).
/// In WebAssembly, which has no multiply that reports an overflow, the builtin is a call to a
/// 128-bit multiply; two factors that fit in 32 bits cannot overflow, so their product is taken
/// directly (matmul ran 7% of its time in that call).
inline bool mulOverflows(int64_t a, int64_t b, int64_t* r) {
#ifdef __wasm__
  if (a == static_cast<int32_t>(a) && b == static_cast<int32_t>(b)) [[likely]] {
    *r = a * b;
    return false;
  }
#endif
  return __builtin_mul_overflow(a, b, r);
}

}  // namespace rb
