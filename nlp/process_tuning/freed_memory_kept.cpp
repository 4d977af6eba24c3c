#include "freed_memory_kept.hpp"

#include <cstdlib>  // defines __GLIBC__ with glibc
#include <mutex>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace dc {

#if defined(__GLIBC__)
namespace {
// glibc's defaults (malloc.c: DEFAULT_MMAP_MAX, DEFAULT_TRIM_THRESHOLD).
constexpr int kDefaultMmapMax = 65536;
constexpr int kDefaultTrimThreshold = 128 * 1024;

std::mutex scopes_mutex;
int keeping_scopes_open = 0;  // across threads
}  // namespace

FreedMemoryKept::FreedMemoryKept() {
  const std::lock_guard<std::mutex> lock(scopes_mutex);
  if (keeping_scopes_open++ > 0) return;
  mallopt(M_MMAP_MAX, 0);              // large blocks from the heap (threads' arenas still mmap)
  // ... and left there when freed: -1 never trims (the largest int, 2 GB, still gave back the
  // 50k-dof body's workspace at every factorisation).
  mallopt(M_TRIM_THRESHOLD, -1);
}

FreedMemoryKept::~FreedMemoryKept() {
  const std::lock_guard<std::mutex> lock(scopes_mutex);
  if (--keeping_scopes_open > 0) return;
  mallopt(M_MMAP_MAX, kDefaultMmapMax);
  mallopt(M_TRIM_THRESHOLD, kDefaultTrimThreshold);
  malloc_trim(0);
}
#else
FreedMemoryKept::FreedMemoryKept() = default;
FreedMemoryKept::~FreedMemoryKept() = default;
#endif

}  // namespace dc
