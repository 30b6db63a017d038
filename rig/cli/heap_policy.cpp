#include "rig/cli/heap_policy.hpp"

#include <malloc.h>

namespace hilrig::cli {

bool keep_freed_heap() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  return false; // the sanitizer's allocator, not glibc's: mallopt would set nothing it uses
#else
  // Blocks up to 32 MiB (glibc's ceiling for this setting) come from the heap, not a mapping
  // of their own; setting it also stops glibc from moving the threshold itself.
  constexpr int kLargestHeapBlock = 32 * 1024 * 1024;
  // Never give the heap's free top back (a threshold beyond any run's heap).
  constexpr int kNeverTrim = 1 << 30;
  return mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock) == 1 && mallopt(M_TRIM_THRESHOLD, kNeverTrim) == 1;
#endif
}

} // namespace hilrig::cli
