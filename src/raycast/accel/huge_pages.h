#pragma once
// Large build buffers backed by transparent huge pages where the kernel offers them on request
// (Linux `madvise` mode): filling a fresh 4 KB page costs a page fault, and at tens of millions
// of primitives those faults cost as much as the build itself (docs/performance-mesh.md, "Build").
#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace raycast {

/// Asks the kernel to back the 2 MB-aligned interior of [p, p + bytes) with huge pages. A hint:
/// does nothing where unsupported, on small ranges or on failure; contents are unchanged.
inline void advise_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t lo = (begin + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t hi = (begin + bytes) & ~(kHuge - 1);
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

/// Resizes an empty vector to n value-initialised elements, its storage advised as above before
/// the elements are first written.
template <class T>
void resize_huge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
  v.resize(n);
}

}  // namespace raycast
