#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

#include "base/large_memory.h"

using namespace rb;

TEST_CASE("large memory: small and screen-sized blocks are writable and aligned", "[base]") {
  // Below 1 MiB from the heap (prepared from 64 KiB), above it mapped (on Linux outside the
  // sanitizer builds): every byte of each can be written and read back, and blocks do not
  // overlap.
  for (size_t bytes : {size_t{16}, size_t{4096}, size_t{100} << 10, size_t{1} << 20, size_t{1920000}, size_t{5} << 20}) {
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

TEST_CASE("large memory: preparing a heap block keeps what it holds", "[base]") {
  // prepareLarge is advice: whatever the system does with it (huge pages inside the block,
  // its pages mapped at once), bytes already written stay and the rest can be written.
  for (size_t bytes : {size_t{100}, size_t{100} << 10, size_t{3} << 20, (size_t{5} << 20) + 12345}) {
    INFO(bytes << " bytes");
    std::vector<uint8_t> block(bytes);
    for (size_t i = 0; i < bytes / 2; ++i) block[i] = static_cast<uint8_t>(i * 7);
    prepareLarge(block.data() + 1, bytes - 1);  // not aligned to anything
    size_t wrong = 0;
    for (size_t i = 0; i < bytes / 2; ++i) wrong += block[i] != static_cast<uint8_t>(i * 7);
    CHECK(wrong == 0);
    for (size_t i = bytes / 2; i < bytes; ++i) block[i] = static_cast<uint8_t>(i);
    CHECK(block[bytes - 1] == static_cast<uint8_t>(bytes - 1));
  }
}
