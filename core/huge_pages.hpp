#pragma once
// Large result buffers backed by transparent huge pages (Linux, THP "madvise" mode). A buffer
// of 100 MB faults in 25 600 pages of 4 KiB on its first touch; on a virtual machine each fault
// costs tens of microseconds (a 150 MB subsurface field: 2.2 s of page faults against 0.09 s
// with 2 MiB pages, docs/subsurface.md "Speed"). madvise(MADV_HUGEPAGE) on the whole 2 MiB
// pages of the buffer's range, before it is touched, lets the kernel map it in 2 MiB pages.
// Only advice: where huge pages are off or not available the buffer is the same, 4 KiB pages.
#include <cstddef>
#include <vector>

namespace dc {

/// Advises the kernel to back the whole 2 MiB pages inside [data, data + bytes) with huge
/// pages. A no-op off Linux, for small ranges, and where the kernel refuses.
void advise_huge_pages(const void* data, std::size_t bytes);

/// v.resize(n) on an empty vector with huge pages advised first (the elements are value-
/// initialised by resize, after the advice, so their first touch maps huge pages).
template <class T>
void resize_on_huge_pages(std::vector<T>& v, std::size_t n) {
  v.clear();
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
  v.resize(n);
}

}  // namespace dc
