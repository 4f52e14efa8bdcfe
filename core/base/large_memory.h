#pragma once
// Memory for large blocks that are filled soon after they are made: whole screens (the canvas,
// its saveScr copy, a flipped frame: 480,000 pixels, 1.9 MB each) and the chunks of a big
// program's compact statements (rb check). On Linux a block of 1 MiB or more is mapped with
// its pages at once, in 2 MiB huge pages where the kernel allows it (transparent huge pages in
// "madvise" or "always" mode) and the block needs at most two of them: a fresh screen then
// costs one page fault instead of about 470, which on some virtual machines took longer than
// the rest of a short program's run. Bigger blocks (a big array, a big program's text) get
// small pages, mapped at once: see large_memory.cpp for why. Smaller blocks, every block elsewhere, and every block in the sanitizer builds (so that
// AddressSanitizer still guards them) are ordinary heap memory.

#include <cstddef>

namespace rb {

/// Blocks of at least this many bytes are the ones mapped in huge pages (where they are).
inline constexpr std::size_t kLargeBlock = std::size_t{1} << 20;
/// Blocks of at least this many bytes are the ones prepareLarge maps at once.
inline constexpr std::size_t kPreparedFrom = std::size_t{64} << 10;

/// At least `bytes` of memory, aligned for any fundamental type; throws std::bad_alloc. A block
/// under kLargeBlock is heap memory, prepared (prepareLarge) from kPreparedFrom.
void* allocateLarge(std::size_t bytes);
/// Gives back a block from allocateLarge of the same size.
void freeLarge(void* p, std::size_t bytes) noexcept;

/// For a block of ordinary memory (a std::string's or std::vector's) that is about to be
/// written whole: where large memory is mapped, maps its pages at once (one call instead of a
/// page fault for each: 16 or more of them) and asks for the huge pages that fit inside it;
/// nothing for a block under kPreparedFrom, or elsewhere. Only advice: the memory is the same,
/// however the system answers.
void prepareLarge(void* p, std::size_t bytes) noexcept;

/// An allocator for containers whose storage is large (a screen of pixels).
template <typename T>
struct LargeAllocator {
  using value_type = T;
  LargeAllocator() noexcept = default;
  template <typename U>
  LargeAllocator(const LargeAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) { return static_cast<T*>(allocateLarge(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { freeLarge(p, n * sizeof(T)); }
  template <typename U>
  friend bool operator==(const LargeAllocator&, const LargeAllocator<U>&) noexcept { return true; }
};

}  // namespace rb
