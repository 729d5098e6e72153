// The BVH returns exactly the brute-force closest hit (same t, same primitive) on random scenes and rays, including
// turned boxes, porous volumes and primitives that exist only for part of the time.
#include <gtest/gtest.h>

#include "sgtllc/sim/bvh.h"
#include "sgtllc/sim/rng.h"

namespace sgtllc::sim {
namespace {

std::vector<Primitive> randomScene(uint64_t seed, int count) {
  Rng rng(seed);
  std::vector<Primitive> prims;
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector2f xy(static_cast<float>(rng.uniform(-60, 60)), static_cast<float>(rng.uniform(-60, 60)));
    Primitive p;
    switch (rng.uniformInt(0, 2)) {
      case 0:
        p = makeBox(xy, static_cast<float>(rng.uniform(-1, 1)), static_cast<float>(rng.uniform(0.1, 12)),
                    static_cast<float>(rng.uniform(0.05, 8)), static_cast<float>(rng.uniform(0.5, 15)),
                    static_cast<float>(rng.uniform(-M_PI, M_PI)), 50, static_cast<uint32_t>(i));
        break;
      case 1:
        p = makeCylinder(xy, static_cast<float>(rng.uniform(-1, 1)), static_cast<float>(rng.uniform(0.03, 0.5)),
                         static_cast<float>(rng.uniform(1, 9)), 80, static_cast<uint32_t>(i));
        break;
      default:
        p = makeEllipsoid(Eigen::Vector3f(xy.x(), xy.y(), static_cast<float>(rng.uniform(0, 6))),
                          Eigen::Vector3f(rng.uniform(0.3, 4), rng.uniform(0.3, 4), rng.uniform(0.3, 3)).cast<float>(),
                          70, static_cast<uint32_t>(i));
        if (rng.chance(0.7)) p.mean_free_path = static_cast<float>(rng.uniform(0.2, 1.0));
    }
    if (rng.chance(0.2)) {
      p.t_begin = static_cast<float>(rng.uniform(0, 50));
      p.t_end = p.t_begin + static_cast<float>(rng.uniform(0, 50));
    }
    prims.push_back(p);
  }
  return prims;
}

void expectSameAsBruteForce(const Bvh& bvh, uint64_t seed, int rays) {
  Rng rng(seed);
  int hits = 0;
  for (int k = 0; k < rays; ++k) {
    const Eigen::Vector3f o(static_cast<float>(rng.uniform(-70, 70)), static_cast<float>(rng.uniform(-70, 70)),
                            static_cast<float>(rng.uniform(0, 5)));
    // Aim at a random point of the scene's bounds, so small scenes get hit too.
    const Aabb box = bvh.bounds();
    Eigen::Vector3f target;
    for (int a = 0; a < 3; ++a) target[a] = static_cast<float>(rng.uniform(box.lo[a] - 1.0, box.hi[a] + 1.0));
    Eigen::Vector3f d = target - o;
    if (k % 50 == 0) d = Eigen::Vector3f(1, 0, 0);  // axis-parallel rays exercise the slab edge cases
    const Ray ray(o, d.normalized());
    const RayContext ctx{static_cast<float>(rng.uniform(0, 100)), rng.next()};
    const float t_max = static_cast<float>(rng.uniform(10, 150));
    const Hit a = bvh.closestHit(ray, t_max, ctx);
    const Hit b = closestHitBruteForce(bvh.primitives(), ray, t_max, ctx);
    ASSERT_EQ(a.prim, b.prim) << "ray " << k;
    if (a.valid()) {
      ASSERT_EQ(a.t, b.t) << "ray " << k;
      ++hits;
    }
  }
  EXPECT_GT(hits, rays / 10);
}

TEST(SimBvh, ClosestHitEqualsBruteForce) {
  for (int leaf : {1, 4, 8}) {
    const Bvh bvh(randomScene(3, 800), leaf);
    ASSERT_EQ(bvh.size(), 800u);
    expectSameAsBruteForce(bvh, 17 + leaf, 4000);
  }
}

TEST(SimBvh, DenseClusterAndTinyScenes) {
  // Everything in one spot (degenerate centroid bounds) and scenes of one or two primitives.
  std::vector<Primitive> same(50, makeCylinder(Eigen::Vector2f(0, 0), 0.0f, 0.3f, 3.0f, 80, 0));
  for (size_t i = 0; i < same.size(); ++i) same[i].half.x() = 0.1f + 0.01f * i;
  expectSameAsBruteForce(Bvh(same), 5, 500);
  expectSameAsBruteForce(Bvh(randomScene(9, 1)), 6, 500);
  expectSameAsBruteForce(Bvh(randomScene(10, 2)), 7, 500);
}

TEST(SimBvh, EmptyBvhMisses) {
  const Bvh empty;
  EXPECT_FALSE(empty.closestHit(Ray(Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitX()), 100.0f, {}).valid());
  EXPECT_FALSE(Bvh(std::vector<Primitive>{}).closestHit(Ray(Eigen::Vector3f::Zero(), Eigen::Vector3f::UnitX()),
                                                        100.0f, {}).valid());
}

TEST(SimBvh, OcclusionNearestWins) {
  // A pole in front of a wall: the pole is hit, the wall behind it is not.
  const Bvh bvh({makeBox(Eigen::Vector2f(10, 0), 0.0f, 0.3f, 20.0f, 5.0f, 0.0f, 50, 0),
                 makeCylinder(Eigen::Vector2f(5, 0), 0.0f, 0.1f, 5.0f, 80, 1)});
  const Hit h = bvh.closestHit(Ray(Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(1, 0, 0)), 100.0f, {});
  ASSERT_TRUE(h.valid());
  EXPECT_EQ(bvh.primitives()[h.prim].semantic, 80);
  EXPECT_NEAR(h.t, 4.9f, 1e-4f);
  const Hit beside = bvh.closestHit(Ray(Eigen::Vector3f(0, 0.5f, 1), Eigen::Vector3f(1, 0, 0)), 100.0f, {});
  EXPECT_EQ(bvh.primitives()[beside.prim].semantic, 50);
  EXPECT_NEAR(beside.t, 9.85f, 1e-4f);
}

}  // namespace
}  // namespace sgtllc::sim
