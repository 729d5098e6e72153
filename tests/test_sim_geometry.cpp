// Ray intersection of the simulator's primitives and ground against analytic answers: hits, misses, rays starting
// inside, grazing rays, porous volumes, time limits and the height-field ground.
#include <gtest/gtest.h>

#include <cmath>

#include "sgtllc/sim/geometry.h"
#include "sgtllc/sim/ground.h"
#include "sgtllc/sim/rng.h"

namespace sgtllc::sim {
namespace {

using Eigen::Vector2f;
using Eigen::Vector3f;

constexpr float kTol = 1e-4f;

/// First crossing with a solid primitive (u is irrelevant for solids).
bool hit(const Primitive& p, const Ray& r, float& t, float t_max = 1e6f) { return intersect(p, r, 0.0f, t_max, 0.0, t); }

Primitive unitBox() { return makeBox(Vector2f(0, 0), -1.0f, 2.0f, 2.0f, 2.0f, 0.0f, 50, 0); }  // [-1, 1]^3

TEST(SimGeometry, BoxFrontFaceHitMissAndBehind) {
  const Primitive box = unitBox();
  float t;
  ASSERT_TRUE(hit(box, Ray(Vector3f(-5, 0.3f, 0.2f), Vector3f(1, 0, 0)), t));
  EXPECT_NEAR(t, 4.0f, kTol);
  EXPECT_FALSE(hit(box, Ray(Vector3f(-5, 1.5f, 0), Vector3f(1, 0, 0)), t));  // passes beside
  EXPECT_FALSE(hit(box, Ray(Vector3f(5, 0, 0), Vector3f(1, 0, 0)), t));     // box behind the origin
  EXPECT_FALSE(hit(box, Ray(Vector3f(-5, 0, 0), Vector3f(1, 0, 0)), t, 3.9f));  // beyond t_max
  // Diagonal ray onto the edge at (−1, −1): both slabs open at the same t = 2√2.
  ASSERT_TRUE(hit(box, Ray(Vector3f(-3, -3, 0), Vector3f(1, 1, 0).normalized()), t));
  EXPECT_NEAR(t, 2.0f * std::sqrt(2.0f), kTol);
}

TEST(SimGeometry, BoxFromInsideHitsTheExit) {
  float t;
  ASSERT_TRUE(hit(unitBox(), Ray(Vector3f(0.5f, 0, 0), Vector3f(0, 0, 1)), t));
  EXPECT_NEAR(t, 1.0f, kTol);
  ASSERT_TRUE(hit(unitBox(), Ray(Vector3f(0.5f, 0, 0), Vector3f(-1, 0, 0)), t));
  EXPECT_NEAR(t, 1.5f, kTol);
}

TEST(SimGeometry, BoxGrazingAlongAFaceCountsAsTouching) {
  float t;
  // In the plane y = 1 of a face: the closed box is touched along the face.
  ASSERT_TRUE(hit(unitBox(), Ray(Vector3f(-5, 1.0f, 0), Vector3f(1, 0, 0)), t));
  EXPECT_NEAR(t, 4.0f, kTol);
  EXPECT_FALSE(hit(unitBox(), Ray(Vector3f(-5, 1.001f, 0), Vector3f(1, 0, 0)), t));
}

TEST(SimGeometry, TurnedBoxUsesItsYaw) {
  // 4 m long along 90° (the y axis), 1 m wide: from the side (along x) it is 1 m thick.
  const Primitive box = makeBox(Vector2f(10, 0), 0.0f, 4.0f, 1.0f, 3.0f, static_cast<float>(M_PI / 2), 50, 0);
  float t;
  ASSERT_TRUE(hit(box, Ray(Vector3f(0, 1.9f, 1), Vector3f(1, 0, 0)), t));
  EXPECT_NEAR(t, 9.5f, kTol);
  EXPECT_FALSE(hit(box, Ray(Vector3f(0, 2.1f, 1), Vector3f(1, 0, 0)), t));
  EXPECT_FALSE(hit(box, Ray(Vector3f(0, 0, 3.1f), Vector3f(1, 0, 0)), t));  // over the top
  const Aabb b = bounds(box);
  EXPECT_NEAR(b.lo.y(), -2.0f, kTol);
  EXPECT_NEAR(b.hi.x(), 10.5f, kTol);
}

TEST(SimGeometry, CylinderSideCapInsideAndTangent) {
  const Primitive c = makeCylinder(Vector2f(0, 0), 0.0f, 0.5f, 4.0f, 80, 0);  // r = 0.5, z in [0, 4]
  float t;
  ASSERT_TRUE(hit(c, Ray(Vector3f(-10, 0, 2), Vector3f(1, 0, 0)), t));
  EXPECT_NEAR(t, 9.5f, kTol);
  // Off-centre: chord at y = 0.3 enters at x = −0.4.
  ASSERT_TRUE(hit(c, Ray(Vector3f(-10, 0.3f, 2), Vector3f(1, 0, 0)), t));
  EXPECT_NEAR(t, 9.6f, kTol);
  ASSERT_TRUE(hit(c, Ray(Vector3f(0.1f, 0, 10), Vector3f(0, 0, -1)), t));  // top cap, vertical ray
  EXPECT_NEAR(t, 6.0f, kTol);
  const Ray slanted(Vector3f(-2, 0, 8), Vector3f(2, 0, -4).normalized());  // passes over the rim, onto the cap
  ASSERT_TRUE(hit(c, slanted, t));
  EXPECT_NEAR(slanted.at(t).z(), 4.0f, 1e-4f);
  EXPECT_NEAR(slanted.at(t).x(), 0.0f, 1e-4f);
  const Ray low(Vector3f(-10, 0, 6), Vector3f(10, 0, -3).normalized());  // reaches the side below the rim
  ASSERT_TRUE(hit(c, low, t));
  EXPECT_NEAR(low.at(t).x(), -0.5f, 1e-4f);
  EXPECT_FALSE(hit(c, Ray(Vector3f(-10, 0, 4.5f), Vector3f(1, 0, 0)), t));  // above
  ASSERT_TRUE(hit(c, Ray(Vector3f(0, 0, 1), Vector3f(1, 0, 0)), t));        // inside: exit
  EXPECT_NEAR(t, 0.5f, kTol);
  ASSERT_TRUE(hit(c, Ray(Vector3f(-10, 0.5f, 2), Vector3f(1, 0, 0)), t));  // tangent touches
  EXPECT_NEAR(t, 10.0f, 1e-3f);
  EXPECT_FALSE(hit(c, Ray(Vector3f(-10, 0.501f, 2), Vector3f(1, 0, 0)), t));
}

TEST(SimGeometry, EllipsoidHitsInsideAndTangent) {
  const Primitive e = makeEllipsoid(Vector3f(0, 0, 5), Vector3f(2, 1, 0.5f), 70, 0);
  float t;
  ASSERT_TRUE(hit(e, Ray(Vector3f(-10, 0, 5), Vector3f(1, 0, 0)), t));
  EXPECT_NEAR(t, 8.0f, kTol);
  ASSERT_TRUE(hit(e, Ray(Vector3f(0, -10, 5), Vector3f(0, 1, 0)), t));
  EXPECT_NEAR(t, 9.0f, kTol);
  ASSERT_TRUE(hit(e, Ray(Vector3f(0, 0, 0), Vector3f(0, 0, 1)), t));
  EXPECT_NEAR(t, 4.5f, kTol);
  // x²/4 + z²/0.25 = 1 at z = 0.25: x = ±√3.
  ASSERT_TRUE(hit(e, Ray(Vector3f(-10, 0, 5.25f), Vector3f(1, 0, 0)), t));
  EXPECT_NEAR(t, 10.0f - std::sqrt(3.0f), 1e-3f);
  ASSERT_TRUE(hit(e, Ray(Vector3f(0.5f, 0, 5), Vector3f(1, 0, 0)), t));  // inside: exit
  EXPECT_NEAR(t, 1.5f, kTol);
  ASSERT_TRUE(hit(e, Ray(Vector3f(-10, 1.0f, 5), Vector3f(1, 0, 0)), t));  // tangent at (0, 1, 5)
  EXPECT_NEAR(t, 10.0f, 1e-2f);
  EXPECT_FALSE(hit(e, Ray(Vector3f(-10, 1.01f, 5), Vector3f(1, 0, 0)), t));
}

TEST(SimGeometry, PorousVolumeReturnsFromItsDepthOrPassesThrough) {
  Primitive e = makeEllipsoid(Vector3f(0, 0, 0), Vector3f(2, 2, 2), 70, 0);
  e.mean_free_path = 0.5f;
  const Ray r(Vector3f(-10, 0, 0), Vector3f(1, 0, 0));
  float t;
  ASSERT_TRUE(intersect(e, r, 0.0f, 1e6f, 0.0, t));
  EXPECT_NEAR(t, 8.0f, kTol);  // u = 0: at the entry
  const double u = 1.0 - std::exp(-2.0);  // depth = −ln(1 − u) · 0.5 = 1 m
  ASSERT_TRUE(intersect(e, r, 0.0f, 1e6f, u, t));
  EXPECT_NEAR(t, 9.0f, 1e-3f);
  EXPECT_FALSE(intersect(e, r, 0.0f, 1e6f, 1.0 - std::exp(-10.0), t));  // 5 m deep: through the 4 m crown
}

TEST(SimGeometry, TimeLimitedPrimitiveIsAliveInItsInterval) {
  Primitive p = unitBox();
  p.t_begin = 10.0f;
  p.t_end = 20.0f;
  EXPECT_FALSE(p.aliveAt(9.99f));
  EXPECT_TRUE(p.aliveAt(10.0f));
  EXPECT_FALSE(p.aliveAt(20.0f));
}

TEST(SimGeometry, NormalsPointOutwards) {
  EXPECT_TRUE(normalAt(unitBox(), Vector3f(-1, 0.2f, 0.1f)).isApprox(Vector3f(-1, 0, 0)));
  EXPECT_TRUE(normalAt(unitBox(), Vector3f(0.1f, 0.2f, 1)).isApprox(Vector3f(0, 0, 1)));
  const Primitive c = makeCylinder(Vector2f(0, 0), 0.0f, 0.5f, 4.0f, 80, 0);
  EXPECT_TRUE(normalAt(c, Vector3f(0, 0.5f, 2)).isApprox(Vector3f(0, 1, 0)));
  EXPECT_TRUE(normalAt(c, Vector3f(0.1f, 0, 4)).isApprox(Vector3f(0, 0, 1)));
  const Primitive e = makeEllipsoid(Vector3f(0, 0, 0), Vector3f(2, 1, 1), 70, 0);
  EXPECT_TRUE(normalAt(e, Vector3f(2, 0, 0)).isApprox(Vector3f(1, 0, 0)));
}

TEST(SimGeometry, AabbSlabTest) {
  Aabb b;
  b.grow(Vector3f(0, 0, 0));
  b.grow(Vector3f(1, 1, 1));
  float t;
  ASSERT_TRUE(b.hit(Ray(Vector3f(-1, 0.5f, 0.5f), Vector3f(1, 0, 0)), 0.0f, 100.0f, t));
  EXPECT_NEAR(t, 1.0f, kTol);
  EXPECT_FALSE(b.hit(Ray(Vector3f(-1, 1.5f, 0.5f), Vector3f(1, 0, 0)), 0.0f, 100.0f, t));
  EXPECT_FALSE(b.hit(Ray(Vector3f(-1, 0.5f, 0.5f), Vector3f(1, 0, 0)), 0.0f, 0.5f, t));
  EXPECT_NEAR(b.area(), 6.0f, kTol);
}

/// First ground crossing by fine marching and bisection: the reference for GroundHeight::intersect.
bool marchGround(const GroundHeight& g, const Ray& r, float t_max, double& t) {
  auto f = [&](double s) {
    const Eigen::Vector3d x = r.o.cast<double>() + s * r.d.cast<double>();
    return x.z() - g.height(x.x(), x.y());
  };
  double prev = 0.0;
  for (double s = 0.01; s <= t_max; s += 0.01) {
    if (f(s) <= 0.0) {
      double lo = prev, hi = s;
      for (int k = 0; k < 60; ++k) (f(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
      t = 0.5 * (lo + hi);
      return true;
    }
    prev = s;
  }
  return false;
}

TEST(SimGeometry, GroundIntersectionMatchesMarching) {
  const GroundHeight g(7, 3.0);
  ASSERT_GT(g.maxSlope(), 0.02);
  Rng rng(11);
  int hits = 0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector2d xy(rng.uniform(-300, 300), rng.uniform(-300, 300));
    const Vector3f o(xy.x(), xy.y(), static_cast<float>(g.height(xy.x(), xy.y()) + 1.73));
    const double az = rng.uniform(0, 2 * M_PI), el = -rng.uniform(0.0, 25.0) * M_PI / 180.0;
    const Ray r(o, Vector3f(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)));
    float t = 0;
    double ref = 0;
    const bool got = g.intersect(r, 120.0f, t), want = marchGround(g, r, 120.0f, ref);
    ASSERT_EQ(got, want) << "ray " << k << " elevation " << el * 180 / M_PI;
    if (got) {
      EXPECT_NEAR(t, ref, 0.02) << "ray " << k;
      ++hits;
    }
  }
  EXPECT_GT(hits, 150);
  // Upward rays never reach the ground; an origin below the ground sees none.
  float t;
  EXPECT_FALSE(g.intersect(Ray(Vector3f(0, 0, static_cast<float>(g.height(0, 0) + 1)), Vector3f(1, 0, 0.2f)), 1e3f, t));
  EXPECT_FALSE(g.intersect(Ray(Vector3f(0, 0, static_cast<float>(g.height(0, 0) - 1)), Vector3f(1, 0, -0.2f)), 1e3f, t));
}

TEST(SimGeometry, FlatGroundIsExact) {
  const GroundHeight flat(3, 0.0);
  float t;
  ASSERT_TRUE(flat.intersect(Ray(Vector3f(0, 0, 1.73f), Vector3f(1, 0, -1).normalized()), 120.0f, t));
  EXPECT_NEAR(t, 1.73f * std::sqrt(2.0f), kTol);
}

TEST(SimGeometry, ZoneMapPaintsByPriority) {
  ZoneMap map(Eigen::Vector2d(0, 0), Eigen::Vector2d(20, 20), 0.25, Zone::kLot, Zone::kField);
  map.paintSegment(Eigen::Vector2d(0, 10), Eigen::Vector2d(20, 10), 5.0, Zone::kSidewalk);
  map.paintSegment(Eigen::Vector2d(0, 10), Eigen::Vector2d(20, 10), 3.0, Zone::kRoad);
  map.paintSegment(Eigen::Vector2d(0, 10), Eigen::Vector2d(20, 10), 4.0, Zone::kParking);  // road keeps priority
  EXPECT_EQ(map.at(5, 10), Zone::kRoad);
  EXPECT_EQ(map.at(5, 13.5), Zone::kParking);
  EXPECT_EQ(map.at(5, 14.5), Zone::kSidewalk);
  EXPECT_EQ(map.at(5, 16), Zone::kLot);
  EXPECT_EQ(map.at(-5, 10), Zone::kField);
  EXPECT_EQ(groundSemantic(Zone::kRoad), 40);
  EXPECT_EQ(groundSemantic(Zone::kLawn), 72);
}

}  // namespace
}  // namespace sgtllc::sim
