// Freed memory kept for the next frame (memory_reuse.h). glibc hands a freed block back to the system when it was
// mapped on its own (blocks over the mmap threshold) or when the free space at the top of the heap exceeds the trim
// threshold; both start at 128 KB, and although the mmap threshold rises once a large block is freed, the trim
// threshold then follows at only twice it. Setting both fixes them: blocks under half of keep_bytes come from the
// heap, and up to keep_bytes of free space stays there. hugePageHeap then marks the heap's next stretch for huge
// pages, so those blocks' first touches fault in 2 MB at a time.
#include "sgtllc/memory_reuse.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
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

bool hugePageHeap(std::size_t bytes) {
#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
  // Probes under reuseFreedMemory's mmap threshold, taken until one makes the heap grow: the free space a process
  // already holds (after a few frames, up to the trim threshold) serves the first ones.
  constexpr std::size_t kProbe = std::size_t{1} << 20;
  constexpr int kMaxProbes = 128;
  constexpr int kDefaultTopPad = 128 << 10;  // mallopt(3)
  bytes = std::min<std::size_t>(bytes, std::size_t{1} << 30);
  if (bytes < 2 * kHugePage || mallopt(M_TOP_PAD, static_cast<int>(bytes)) != 1) return false;
  void* probes[kMaxProbes];
  int taken = 0;
  char* grown_from = nullptr;
  char* grown_to = nullptr;
  while (taken < kMaxProbes) {
    char* const before = static_cast<char*>(sbrk(0));
    probes[taken] = std::malloc(kProbe);
    if (probes[taken] == nullptr) break;
    char* const probe = static_cast<char*>(probes[taken++]);
    char* const after = static_cast<char*>(sbrk(0));
    // A block mapped on its own (a sanitizer's allocator, or glibc above its mmap threshold) lies above the heap:
    // the heap will not grow for these probes.
    if (before == reinterpret_cast<char*>(-1) || probe >= after) break;
    // Only a growth by the pad with the probe in it; a probe below the old break came from free space.
    if (probe + kProbe > before && after > before && static_cast<std::size_t>(after - before) >= bytes / 2) {
      grown_from = before;
      grown_to = after;
      break;
    }
  }
  bool marked = false;
  if (grown_to != nullptr) {
    const std::uintptr_t start = (reinterpret_cast<std::uintptr_t>(grown_from) + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t end = reinterpret_cast<std::uintptr_t>(grown_to) & ~(kHugePage - 1);
    marked = end > start && madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE) == 0;
  }
  while (taken > 0) std::free(probes[--taken]);
  // Unmarked, the heap grows by glibc's default again.
  if (!marked) mallopt(M_TOP_PAD, kDefaultTopPad);
  return marked;
#else
  (void)bytes;
  return false;
#endif
}

}  // namespace sgtllc
