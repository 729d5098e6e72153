// Freed memory kept for the next frame (memory_reuse.h). glibc hands a freed block back to the system when it was
// mapped on its own (blocks over the mmap threshold) or when the free space at the top of the heap exceeds the trim
// threshold; both start at 128 KB, and although the mmap threshold rises once a large block is freed, the trim
// threshold then follows at only twice it. Setting both fixes them: blocks under half of keep_bytes come from the
// heap, and up to keep_bytes of free space stays there.
#include "sgtllc/memory_reuse.h"

#include <algorithm>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace sgtllc {

bool reuseFreedMemory(std::size_t keep_bytes) {
#if defined(__GLIBC__)
  // glibc caps the mmap threshold at 32 MB on 64-bit systems (HEAP_MAX_SIZE / 2) and refuses larger values.
  constexpr std::size_t kMaxMmapThreshold = std::size_t{32} << 20;
  const std::size_t mmap_threshold = std::min(kMaxMmapThreshold, std::max<std::size_t>(keep_bytes / 2, 128 << 10));
  const std::size_t trim_threshold = std::min<std::size_t>(keep_bytes, 1u << 30);
  return mallopt(M_MMAP_THRESHOLD, static_cast<int>(mmap_threshold)) == 1 &&
         mallopt(M_TRIM_THRESHOLD, static_cast<int>(trim_threshold)) == 1;
#else
  (void)keep_bytes;
  return false;
#endif
}

}  // namespace sgtllc
