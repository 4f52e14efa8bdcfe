#include "base/large_memory.h"

#include <cstdint>
#include <new>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RB_LARGE_MEMORY_PLAIN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define RB_LARGE_MEMORY_PLAIN 1
#endif
#if defined(__linux__) && !defined(RB_LARGE_MEMORY_PLAIN)
#include <sys/mman.h>
#define RB_LARGE_MEMORY_MAPPED 1
#endif

namespace rb {

#if defined(RB_LARGE_MEMORY_MAPPED)
namespace {
constexpr std::size_t kHuge = std::size_t{2} << 20;  // the x86-64 and arm64 huge page
constexpr std::size_t kHugeAdvisedUpTo = 2 * kHuge;  // blocks of more get small pages
std::size_t mappedSize(std::size_t bytes) { return (bytes + kHuge - 1) & ~(kHuge - 1); }
}  // namespace

void* allocateLarge(std::size_t bytes) {
  if (bytes < kLargeBlock) {
    void* p = ::operator new(bytes);
    prepareLarge(p, bytes);  // from kPreparedFrom: its pages at once
    return p;
  }
  const std::size_t size = mappedSize(bytes);
  // Map one huge page more than needed and give back what lies outside the aligned block.
  void* raw = mmap(nullptr, size + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (start + kHuge - 1) & ~(kHuge - 1);
  if (aligned > start) munmap(raw, aligned - start);
  const std::uintptr_t end = start + size + kHuge;
  if (end > aligned + size) munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
  void* p = reinterpret_cast<void*>(aligned);
  prepareLarge(p, size);  // aligned to huge pages and a whole number of them: all huge
  return p;
}

void prepareLarge(void* p, std::size_t bytes) noexcept {
  if (bytes < kPreparedFrom) return;
  constexpr std::uintptr_t kPage = 4096;
  const auto start = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t end = start + bytes;
  // Advice only: a range the kernel refuses is left as it was.
#if defined(MADV_HUGEPAGE)  // refused where huge pages are off: small pages then
  // Only a few huge pages: on a virtual machine a fresh huge page may be memory the host has
  // not backed yet, and then costs what its 512 small pages' faults would (about 4 ms on the
  // AMD VM of bench/README.md); a block of many (a 32 MB array) took twice its usual time in
  // about half the runs, which small pages mapped at once never did.
  const std::uintptr_t hugeStart = (start + kHuge - 1) & ~(kHuge - 1), hugeEnd = end & ~(kHuge - 1);
  if (hugeEnd > hugeStart && hugeEnd - hugeStart <= kHugeAdvisedUpTo)
    madvise(reinterpret_cast<void*>(hugeStart), hugeEnd - hugeStart, MADV_HUGEPAGE);
#endif
#if defined(MADV_POPULATE_WRITE)  // Linux 5.14+: the pages mapped in one call
  const std::uintptr_t pageStart = (start + kPage - 1) & ~(kPage - 1), pageEnd = end & ~(kPage - 1);
  if (pageEnd > pageStart) madvise(reinterpret_cast<void*>(pageStart), pageEnd - pageStart, MADV_POPULATE_WRITE);
#endif
}

void freeLarge(void* p, std::size_t bytes) noexcept {
  if (bytes < kLargeBlock) {
    ::operator delete(p);
    return;
  }
  munmap(p, mappedSize(bytes));
}
#else
void* allocateLarge(std::size_t bytes) { return ::operator new(bytes); }
void freeLarge(void* p, std::size_t) noexcept { ::operator delete(p); }
void prepareLarge(void*, std::size_t) noexcept {}
#endif

}  // namespace rb
