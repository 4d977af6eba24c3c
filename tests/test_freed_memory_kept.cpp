// FreedMemoryKept (nlp/process_tuning/freed_memory_kept.hpp): within its scope a large block comes from the
// heap and stays there when freed (MUMPS's next workspace reuses touched pages); after it, glibc
// maps large blocks again and the kept memory is given back.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include "freed_memory_kept.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

constexpr std::size_t kBlock = std::size_t{64} << 20;  // above glibc's largest mmap threshold (32 MB)

#if defined(__GLIBC__)
/// Bytes of the blocks glibc serves by mmap while one block of kBlock is held.
std::size_t mapped_while_held() {
  void* block = std::malloc(kBlock);
  EXPECT_NE(block, nullptr);
  std::memset(block, 1, kBlock);
  const std::size_t mapped = mallinfo2().hblkhd;
  std::free(block);
  return mapped;
}
#endif

TEST(FreedMemoryKept, LargeBlocksComeFromTheHeapAndStayThereWithinTheScope) {
#if defined(__GLIBC__)
  // A sanitizer's allocator replaces glibc's malloc: its mallinfo2 counts none of these blocks.
  if (DYNCONTACT_SANITIZED) GTEST_SKIP() << "the sanitizer's allocator, not glibc's";
  ASSERT_GE(mapped_while_held(), kBlock);  // glibc's default: mapped
  {
    const dc::FreedMemoryKept kept;
    EXPECT_LT(mapped_while_held(), kBlock);        // from the heap
    EXPECT_GE(mallinfo2().fordblks, kBlock);       // freed, kept in the heap
  }
  EXPECT_LT(mallinfo2().fordblks, kBlock);         // given back
  EXPECT_GE(mapped_while_held(), kBlock);          // mapped again
#else
  GTEST_SKIP() << "glibc only";
#endif
}

}  // namespace
