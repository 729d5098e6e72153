// Freed memory kept for the next frame and the heap on huge pages (memory_reuse.h): accepted by glibc (the region
// marked as the kernel reports it), and the labeller's output on a real KITTI scan is the same with them as without.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#if defined(__GLIBC__)
#include <unistd.h>
#endif

#include "sgtllc/label/geometric_labeller.h"
#include "sgtllc/memory_reuse.h"
#include "test_kitti_support.h"

// AddressSanitizer and MemorySanitizer replace glibc's allocator, and their mallopt refuses every setting.
#if defined(__SANITIZE_ADDRESS__)
#define SGTLLC_ALLOCATOR_REPLACED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define SGTLLC_ALLOCATOR_REPLACED 1
#endif
#endif
#ifndef SGTLLC_ALLOCATOR_REPLACED
#define SGTLLC_ALLOCATOR_REPLACED 0
#endif
// ThreadSanitizer leaves mallopt to glibc but serves malloc from its own heap, which never moves the break.
#if defined(__SANITIZE_THREAD__)
#define SGTLLC_HEAP_ELSEWHERE 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define SGTLLC_HEAP_ELSEWHERE 1
#endif
#endif
#ifndef SGTLLC_HEAP_ELSEWHERE
#define SGTLLC_HEAP_ELSEWHERE SGTLLC_ALLOCATOR_REPLACED
#endif

namespace sgtllc {
namespace {

TEST(MemoryReuse, SameLabelsWithFreedMemoryKept) {
  const LabeledCloud scan = test::kittiScan("004501");
  const label::GeometricLabeller labeller{LabellerConfig{}};
  const label::Labelling before = labeller.classify(scan.points);
#if defined(__GLIBC__) && !SGTLLC_ALLOCATOR_REPLACED
  EXPECT_TRUE(reuseFreedMemory());
  EXPECT_TRUE(reuseFreedMemory(std::size_t{1} << 40));  // beyond glibc's caps: clamped, not refused
#else
  EXPECT_FALSE(reuseFreedMemory());
#endif
  for (int run = 0; run < 2; ++run) {
    const label::Labelling after = labeller.classify(scan.points);
    EXPECT_EQ(after.classes, before.classes);
    EXPECT_EQ(after.segment, before.segment);
    EXPECT_EQ(after.ground, before.ground);
  }
  EXPECT_GT(before.segments, 100);
}

#if defined(__GLIBC__)
/// The VmFlags line of the mapping in /proc/self/smaps that holds @p address ("" if none).
std::string vmFlagsAt(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t start = 0, end = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> start >> dash >> end && dash == '-' && line.find(':') > line.find(' ')) {
      inside = start <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}
#endif

/// Whether the kernel offers transparent huge pages to a region that asks for them.
bool kernelOffersHugePages() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return text.find("[always]") != std::string::npos || text.find("[madvise]") != std::string::npos;
}

TEST(MemoryReuse, HeapRegionMarkedForHugePages) {
  const LabeledCloud scan = test::kittiScan("004501");
  const label::GeometricLabeller labeller{LabellerConfig{}};
  const label::Labelling before = labeller.classify(scan.points);
  reuseFreedMemory();
  const bool marked = hugePageHeap();
#if defined(__GLIBC__) && !SGTLLC_HEAP_ELSEWHERE
  if (kernelOffersHugePages()) {
    EXPECT_TRUE(marked);
  }
#else
  EXPECT_FALSE(marked) << "an allocator with a heap of its own; the kernel offers huge pages: "
                       << kernelOffersHugePages();
#endif
#if defined(__GLIBC__)
  // The heap's top, where the next blocks come from, lies in the marked region ("hg" in the mapping's flags:
  // MADV_HUGEPAGE).
  const std::string flags = vmFlagsAt(static_cast<char*>(sbrk(0)) - 1);
  EXPECT_EQ(flags.find(" hg") != std::string::npos, marked) << flags;
  if (marked) {
    EXPECT_FALSE(flags.empty());
  }
#endif
  const label::Labelling after = labeller.classify(scan.points);
  EXPECT_EQ(after.classes, before.classes);
  EXPECT_EQ(after.segment, before.segment);
}

}  // namespace
}  // namespace sgtllc
