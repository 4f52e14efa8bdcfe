#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>

#include "screen/canvas.h"
#include "screen/screen_memory.h"

using namespace rb;

TEST_CASE("screen memory: small and screen-sized blocks are writable and aligned", "[screen]") {
  // Below 1 MiB from the heap, above it mapped (on Linux outside the sanitizer builds): every
  // byte of each can be written and read back, and blocks do not overlap.
  for (size_t bytes : {size_t{16}, size_t{4096}, size_t{1} << 20, size_t{1920000}, size_t{5} << 20}) {
    INFO(bytes << " bytes");
    auto* a = static_cast<uint8_t*>(allocateScreenMemory(bytes));
    auto* b = static_cast<uint8_t*>(allocateScreenMemory(bytes));
    CHECK(reinterpret_cast<uintptr_t>(a) % alignof(std::max_align_t) == 0);
    CHECK((a + bytes <= b || b + bytes <= a));
    std::memset(a, 0xAB, bytes);
    std::memset(b, 0xCD, bytes);
    CHECK(a[0] == 0xAB);
    CHECK(a[bytes - 1] == 0xAB);
    CHECK(b[bytes / 2] == 0xCD);
    freeScreenMemory(a, bytes);
    freeScreenMemory(b, bytes);
  }
}

TEST_CASE("screen memory: a screen of pixels copies, compares and grows like a vector", "[screen]") {
  const size_t n = static_cast<size_t>(Canvas::kWidth) * Canvas::kHeight;
  Pixels screen(n, colours::kWhite);
  screen[n - 1] = colours::kRed;
  Pixels copy = screen;
  CHECK(copy == screen);
  copy[0] = colours::kBlue;
  CHECK(copy != screen);
  copy.resize(2 * n, colours::kGreen);  // moves to a larger block
  CHECK(copy[n - 1] == colours::kRed);
  CHECK(copy[2 * n - 1] == colours::kGreen);
  copy = screen;  // back to the screen's size, in the block it has
  CHECK(copy == screen);
}
