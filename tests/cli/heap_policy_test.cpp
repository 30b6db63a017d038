// keep_freed_heap(): a run's large blocks come from the heap and stay there when freed, so the
// next run reuses pages that are already mapped (rig/cli/heap_policy.hpp). Checked through
// glibc's own accounting (mallinfo2: hblkhd = bytes in blocks mapped on their own, arena =
// bytes of the heap), not timed.

#include <gtest/gtest.h>
#include <malloc.h>

#include <cstddef>
#include <cstdlib>
#include <cstring>

#include "rig/cli/heap_policy.hpp"

namespace hilrig::cli {
namespace {

constexpr std::size_t kMiB = 1024 * 1024;

void* volatile g_sink; // keeps the compiler from eliding a malloc/free pair

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)

TEST(HeapPolicy, ReportsThatASanitizersAllocatorTakesNoGlibcPolicy) { EXPECT_FALSE(keep_freed_heap()); }

#else

// Allocates `bytes`, touches every page, and returns how glibc's two counts moved.
struct Moved {
  long long mapped = 0; // hblkhd after - before
  long long heap = 0;   // arena after - before
};

Moved allocate_touched(std::size_t bytes, void** block) {
  const struct mallinfo2 before = mallinfo2();
  *block = std::malloc(bytes);
  g_sink = *block;
  std::memset(*block, 1, bytes);
  const struct mallinfo2 after = mallinfo2();
  return {static_cast<long long>(after.hblkhd) - static_cast<long long>(before.hblkhd),
          static_cast<long long>(after.arena) - static_cast<long long>(before.arena)};
}

TEST(HeapPolicy, BlocksBelowTheCeilingComeFromTheHeapAndStayThereWhenFreed) {
  ASSERT_TRUE(keep_freed_heap());
  void* block = nullptr;
  // 8 MiB: glibc's default (128 KiB, moving up to the largest block freed) would map it.
  const Moved moved = allocate_touched(8 * kMiB, &block);
  EXPECT_EQ(moved.mapped, 0);
  EXPECT_GE(moved.heap, static_cast<long long>(8 * kMiB));
  const std::size_t heap_before_free = mallinfo2().arena;
  std::free(block);
  EXPECT_EQ(mallinfo2().arena, heap_before_free) << "the freed top was given back to the kernel";
  // The next run's block of the same size is the same pages.
  void* again = std::malloc(8 * kMiB);
  g_sink = again;
  EXPECT_EQ(again, block);
  std::free(again);
}

TEST(HeapPolicy, TheCeilingIs32MiBJustBelowFromTheHeapJustAboveMapped) {
  ASSERT_TRUE(keep_freed_heap());
  void* below = nullptr;
  void* above = nullptr;
  // glibc maps a block whose chunk (request + 8 bytes of header, rounded up to 16) reaches
  // the threshold: 32 MiB - 16 bytes of request is exactly 32 MiB of chunk.
  const Moved under = allocate_touched(32 * kMiB - 32, &below);
  const Moved at = allocate_touched(32 * kMiB - 16, &above);
  EXPECT_EQ(under.mapped, 0);
  EXPECT_GE(at.mapped, static_cast<long long>(32 * kMiB));
  std::free(below);
  std::free(above);
}

#endif

} // namespace
} // namespace hilrig::cli
