#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>

#include "base/large_memory.h"

using namespace rb;

TEST_CASE("large memory: small and screen-sized blocks are writable and aligned", "[base]") {
  // Below 1 MiB from the heap, above it mapped (on Linux outside the sanitizer builds): every
  // byte of each can be written and read back, and blocks do not overlap.
  for (size_t bytes : {size_t{16}, size_t{4096}, size_t{1} << 20, size_t{1920000}, size_t{5} << 20}) {
    INFO(bytes << " bytes");
    auto* a = static_cast<uint8_t*>(allocateLarge(bytes));
    auto* b = static_cast<uint8_t*>(allocateLarge(bytes));
    CHECK(reinterpret_cast<uintptr_t>(a) % alignof(std::max_align_t) == 0);
    CHECK((a + bytes <= b || b + bytes <= a));
    std::memset(a, 0xAB, bytes);
    std::memset(b, 0xCD, bytes);
    CHECK(a[0] == 0xAB);
    CHECK(a[bytes - 1] == 0xAB);
    CHECK(b[bytes / 2] == 0xCD);
    freeLarge(a, bytes);
    freeLarge(b, bytes);
  }
}
