// The world builder's shape helpers must not keep a reference into the primitive list across a later add: a
// reallocation frees the old storage (addHedge once read its first box after adding the second).
//
// A use-after-free usually reads the old, still intact bytes, so the bug shows only under ASan. This executable
// replaces the global allocator with one that overwrites freed memory with 0xA5 (a float of about -2.9e-16), so
// a read through a dangling reference returns garbage in a normal build too, and the tests below fail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>

#include "sim/world_builder.h"

namespace {

// Each block starts with its size, so operator delete can scribble over all of it.
constexpr size_t kHeader = alignof(std::max_align_t);

void* scribblingNew(size_t size) {
  auto* block = static_cast<unsigned char*>(std::malloc(size + kHeader));
  if (!block) throw std::bad_alloc();
  std::memcpy(block, &size, sizeof(size));
  return block + kHeader;
}

void scribblingDelete(void* p) noexcept {
  if (!p) return;
  auto* block = static_cast<unsigned char*>(p) - kHeader;
  size_t size = 0;
  std::memcpy(&size, block, sizeof(size));
  std::memset(p, 0xA5, size);
  std::free(block);
}

}  // namespace

void* operator new(size_t size) { return scribblingNew(size); }
void* operator new[](size_t size) { return scribblingNew(size); }
void operator delete(void* p) noexcept { scribblingDelete(p); }
void operator delete[](void* p) noexcept { scribblingDelete(p); }
void operator delete(void* p, size_t) noexcept { scribblingDelete(p); }
void operator delete[](void* p, size_t) noexcept { scribblingDelete(p); }

namespace sgtllc::sim::detail {
namespace {

World flatWorld(SceneKind kind) {
  World w;
  w.config.preset = scenePreset(kind);
  w.config.seed = 3;
  w.ground = GroundHeight(3, 0.0);
  w.zones = ZoneMap(Eigen::Vector2d(-50, -50), Eigen::Vector2d(50, 50), 0.25, Zone::kLot, Zone::kField);
  return w;
}

/// A builder whose primitive list is full (size == capacity), so the helper's next add reallocates.
void fillToCapacity(WorldBuilder& b) {
  b.prims.assign(1, makeBox(Eigen::Vector2f(40, 40), 0.0f, 1.0f, 1.0f, 1.0f, 0.0f, semantic::kBuilding, 0));
  b.prims.shrink_to_fit();
  ASSERT_EQ(b.prims.capacity(), b.prims.size());
}

void expectPorousVegetation(const Primitive& p) {
  EXPECT_EQ(p.semantic, semantic::kVegetation);
  EXPECT_FLOAT_EQ(p.mean_free_path, 0.3f);
  EXPECT_GE(p.reflectivity, 0.3f);
  EXPECT_LE(p.reflectivity, 0.45f);
}

TEST(SimWorldBuilder, TrimmedHedgeKeepsTheReflectivityWhenTheListReallocates) {
  World w = flatWorld(SceneKind::kSuburban);
  WorldBuilder b(w);
  for (size_t existing : {1, 2, 3, 4, 5, 8, 16}) {  // any fill level: the hedge's second add may reallocate
    fillToCapacity(b);
    while (b.prims.size() < existing) b.prims.push_back(b.prims.front());
    b.prims.shrink_to_fit();
    Rng rng(11, Stream::kVegetation);
    const size_t first = b.prims.size();
    const float change = 42.0f;
    addHedge(b, rng, Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0), change);
    ASSERT_EQ(b.prims.size(), first + 2) << existing;
    const Primitive &full = b.prims[first], &trimmed = b.prims[first + 1];
    expectPorousVegetation(full);
    expectPorousVegetation(trimmed);
    EXPECT_EQ(trimmed.reflectivity, full.reflectivity) << "existing " << existing;  // one hedge, one material
    EXPECT_EQ(full.t_begin, -kInf);
    EXPECT_EQ(full.t_end, change);
    EXPECT_EQ(trimmed.t_begin, change);
    EXPECT_EQ(trimmed.t_end, kInf);
    EXPECT_LT(trimmed.half.z(), full.half.z());  // trimmed lower and thinner
    EXPECT_LT(trimmed.half.y(), full.half.y());
    EXPECT_EQ(full.object, trimmed.object);
  }
}

TEST(SimWorldBuilder, EveryShapeHelperIsWhollyWrittenWhenTheListReallocates) {
  // Trees (trunk + crowns, cut back at the change), bushes and fences, each added to a full list: every field a
  // helper sets after adding must land in the list, not in freed storage.
  World w = flatWorld(SceneKind::kRural);
  WorldBuilder b(w);
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed, Stream::kVegetation);
    fillToCapacity(b);
    addTree(b, rng, Eigen::Vector2d(0, 0), 1.0, 30.0f);
    for (size_t k = 1; k < b.prims.size(); ++k) {
      const Primitive& p = b.prims[k];
      EXPECT_GE(p.reflectivity, 0.25f) << seed << " " << k;
      EXPECT_LE(p.reflectivity, 0.45f) << seed << " " << k;
      if (p.semantic == semantic::kVegetation) {
        EXPECT_GE(p.mean_free_path, 0.45f) << seed << " " << k;
      }
    }
    fillToCapacity(b);
    addBush(b, rng, Eigen::Vector2d(0, 0), 1.0, 30.0f);
    for (size_t k = 1; k < b.prims.size(); ++k) {
      expectPorousVegetation(b.prims[k]);
      EXPECT_EQ(b.prims[k].t_end, 30.0f);
    }
    fillToCapacity(b);
    addFence(b, rng, Eigen::Vector2d(0, 0), Eigen::Vector2d(5, 0));
    ASSERT_EQ(b.prims.size(), 2u);
    EXPECT_EQ(b.prims[1].semantic, semantic::kFence);
    EXPECT_GE(b.prims[1].reflectivity, 0.3f);
    EXPECT_LE(b.prims[1].reflectivity, 0.45f);
  }
}

}  // namespace
}  // namespace sgtllc::sim::detail
