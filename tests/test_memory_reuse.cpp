// Freed memory kept for the next frame (memory_reuse.h): accepted by glibc, and the labeller's output on a real
// KITTI scan is the same with it as without.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace sgtllc
