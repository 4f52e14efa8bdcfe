#pragma once
// Memory for whole screens (the canvas, its saveScr copy, a flipped frame): 480,000 pixels,
// 1.9 MB each. On Linux a block that large is mapped as one 2 MiB huge page where the kernel
// allows it (transparent huge pages in "madvise" or "always" mode), with its pages mapped at
// once: a fresh screen then costs one page fault instead of about 470, which on some virtual
// machines took longer than the rest of a short program's run. Everywhere else, and in the
// sanitizer builds (so that AddressSanitizer still guards the screen), it is ordinary heap
// memory.

#include <cstddef>
#include <vector>

namespace rb {

/// At least `bytes` of memory, aligned for any pixel type; throws std::bad_alloc.
void* allocateScreenMemory(std::size_t bytes);
/// Gives back a block from allocateScreenMemory of the same size.
void freeScreenMemory(void* p, std::size_t bytes) noexcept;

template <typename T>
struct ScreenAllocator {
  using value_type = T;
  ScreenAllocator() noexcept = default;
  template <typename U>
  ScreenAllocator(const ScreenAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) { return static_cast<T*>(allocateScreenMemory(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { freeScreenMemory(p, n * sizeof(T)); }
  template <typename U>
  friend bool operator==(const ScreenAllocator&, const ScreenAllocator<U>&) noexcept { return true; }
};

}  // namespace rb
