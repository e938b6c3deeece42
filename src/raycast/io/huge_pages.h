#pragma once
// Transparent huge pages for large buffers that are filled once (a large scene's nodes and
// objects): a few dozen page faults instead of tens of thousands, which otherwise cost as much
// as filling the buffer.
#include <cstddef>

namespace raycast {

/// The size of a transparent huge page on x86-64 and arm64 Linux.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

/// Advises the kernel to back the whole huge pages inside [p, p + bytes) with transparent huge
/// pages (Linux, when enabled for `madvise`). Advice only: nothing changes where it is refused,
/// and buffers smaller than two huge pages are left alone.
void advise_huge_pages(void* p, std::size_t bytes);

}  // namespace raycast
