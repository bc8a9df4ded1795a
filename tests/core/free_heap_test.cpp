#include "blayer/core/free_heap.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "blayer/core/address_sanitizer.h"

namespace blayer {
namespace {

TEST(FreeHeap, ATunablesValueThatSetsTheMmapThresholdIsTheUsersChoice) {
  EXPECT_FALSE(tunables_choose_mmap_threshold(nullptr));
  EXPECT_FALSE(tunables_choose_mmap_threshold(""));
  EXPECT_FALSE(tunables_choose_mmap_threshold("glibc.malloc.hugetlb=1:glibc.malloc.arena_max=1"));
  EXPECT_TRUE(tunables_choose_mmap_threshold("glibc.malloc.mmap_threshold=65536"));
  EXPECT_TRUE(tunables_choose_mmap_threshold("glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=1048576"));
}

#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
// Bytes in chunks that have mappings of their own.
std::size_t mapped_bytes() { return mallinfo2().hblkhd; }

// glibc's own threshold starts at 128 KiB and rises only to the size of a freed mapped
// chunk: an array of 24 MiB is a mapping of its own unless keep_arrays_in_heap raised it.
TEST(FreeHeap, ArraysUpToTheLimitComeFromTheHeapAndLargerOnesAreMapped) {
  if (kAddressSanitizer) GTEST_SKIP() << "AddressSanitizer's allocator is its own";
  if (tunables_choose_mmap_threshold(std::getenv("GLIBC_TUNABLES"))) GTEST_SKIP() << "GLIBC_TUNABLES chooses it";
  keep_arrays_in_heap();
  const std::size_t before = mapped_bytes();
  const std::size_t below = kHeapArrayLimit - (std::size_t{8} << 20);
  std::unique_ptr<char[]> in_heap(new char[below]);
  in_heap[below - 1] = 1;
  EXPECT_EQ(mapped_bytes(), before);
  const std::size_t above = kHeapArrayLimit + (std::size_t{8} << 20);
  std::unique_ptr<char[]> mapped(new char[above]);
  mapped[above - 1] = 1;
  EXPECT_GE(mapped_bytes(), before + above);
}
#endif

}  // namespace
}  // namespace blayer
