#pragma once
// Memory for large build buffers (references, nodes, permutations of tens of millions of
// primitives). Two costs dominate there once the build itself is fast (perf of
// `raycast bench --procedural sphere:10000000 --build-only`): a page fault and the kernel's zeroing
// for every fresh 4 KB page, and a serial pass that value-initialises a vector before a parallel
// pass overwrites it. BuildAllocator avoids both: it asks for transparent huge pages and leaves
// elements uninitialised, so that the first touch happens in the (parallel) pass that writes them.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
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

/// Resizes an empty vector to n value-initialised elements, its storage advised as huge pages
/// before the (serial) initialisation first touches it.
template <class T, class A>
void resize_huge(std::vector<T, A>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
  v.resize(n);
}

/// A std::allocator whose value-initialisation without arguments (vector::resize(n)) does
/// nothing, and whose large blocks are advised as huge pages. Only for implicit-lifetime types
/// (aggregates and scalars) that every user writes before reading: resize(n) leaves the new
/// elements' values indeterminate.
template <class T>
struct BuildAllocator {
  using value_type = T;
  BuildAllocator() = default;
  template <class U>
  BuildAllocator(const BuildAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) {
    T* p = std::allocator<T>().allocate(n);
    if (n * sizeof(T) >= (std::size_t(4) << 20)) advise_huge_pages(p, n * sizeof(T));
    return p;
  }
  void deallocate(T* p, std::size_t n) noexcept { std::allocator<T>().deallocate(p, n); }
  template <class U>
  void construct(U*) noexcept {}
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const BuildAllocator<U>&) const noexcept {
    return true;
  }
};

/// A vector of build data (see BuildAllocator: resize(n) leaves elements uninitialised).
template <class T>
using BuildVector = std::vector<T, BuildAllocator<T>>;

}  // namespace raycast
