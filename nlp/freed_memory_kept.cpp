#include "freed_memory_kept.hpp"

#include <cstdlib>  // defines __GLIBC__ with glibc

#if defined(__GLIBC__)
#include <malloc.h>

#include <climits>
#endif

namespace dc {

#if defined(__GLIBC__)
namespace {
// glibc's defaults (malloc.c: DEFAULT_MMAP_MAX, DEFAULT_TRIM_THRESHOLD).
constexpr int kDefaultMmapMax = 65536;
constexpr int kDefaultTrimThreshold = 128 * 1024;
}  // namespace

FreedMemoryKept::FreedMemoryKept() {
  mallopt(M_MMAP_MAX, 0);              // large blocks from the heap (threads' arenas still mmap)
  mallopt(M_TRIM_THRESHOLD, INT_MAX);  // ... and left there when freed
}

FreedMemoryKept::~FreedMemoryKept() {
  mallopt(M_MMAP_MAX, kDefaultMmapMax);
  mallopt(M_TRIM_THRESHOLD, kDefaultTrimThreshold);
  malloc_trim(0);
}
#else
FreedMemoryKept::FreedMemoryKept() = default;
FreedMemoryKept::~FreedMemoryKept() = default;
#endif

}  // namespace dc
