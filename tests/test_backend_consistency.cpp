// Pairwise loop consistency (cycle errors against a hand-built odometry) and the greedy maximum clique.
#include <gtest/gtest.h>

#include "sgtllc/backend/loop_consistency.h"
#include "test_backend_support.h"

namespace sgtllc::backend {
namespace {

// Frames on a straight line 1 m apart along x.
OdometryChain line(int frames) {
  OdometryChain chain;
  for (int i = 1; i < frames; ++i) chain.append(test::planarPose({1.0, 0.0, 0.0}, 0.0));
  return chain;
}

Edge loop(int from, int to, const Eigen::Isometry3d& T) {
  Edge e;
  e.from = from;
  e.to = to;
  e.T_from_to = T;
  e.kind = EdgeKind::kLoop;
  return e;
}

TEST(BackendConsistency, CycleErrorOfTwoLoops) {
  const OdometryChain chain = line(100);
  EXPECT_NEAR(chain.pathLength(80, 20), 60.0, 1e-12);
  // Loops that agree with the odometry close their cycle exactly.
  const Edge a = loop(10, 50, test::planarPose({40.0, 0.0, 0.0}, 0.0));
  const Edge b = loop(20, 80, test::planarPose({60.0, 0.0, 0.0}, 0.0));
  CycleError e = cycleError(a, b, chain);
  EXPECT_NEAR(e.translation, 0.0, 1e-9);
  EXPECT_NEAR(e.rotation, 0.0, 1e-12);
  EXPECT_NEAR(e.path_length, 10.0 + 30.0, 1e-9);
  // A loop 2 m off along y and turned by 0.1 rad: the cycle opens by exactly that much.
  const Edge c = loop(20, 80, test::planarPose({60.0, 2.0, 0.0}, 0.1));
  e = cycleError(a, c, chain);
  EXPECT_NEAR(e.rotation, 0.1, 1e-12);
  // E = Z_a⁻¹ · T_10_20 · Z_c · T_80_50 = x(−40) · x(10) · (60, 2, yaw 0.1) · x(−30).
  const Eigen::Isometry3d E = test::planarPose({-30.0, 0.0, 0.0}, 0.0) * test::planarPose({60.0, 2.0, 0.0}, 0.1) *
                              test::planarPose({-30.0, 0.0, 0.0}, 0.0);
  EXPECT_NEAR(e.translation, E.translation().norm(), 1e-9);
  LoopConsistency bounds;
  bounds.translation_m = 1.0;
  bounds.translation_per_m = 0.0;
  EXPECT_FALSE(consistent(e, bounds));
  bounds.translation_per_m = 0.1;  // 1 + 0.1 · 40 m > the 3.x m opening
  bounds.rotation_rad = 0.05;
  bounds.rotation_per_m = 0.002;   // 0.05 + 0.08 > 0.1
  EXPECT_TRUE(consistent(e, bounds));
}

// Five good loops, two bad ones consistent with each other and with one good loop: the clique is the five.
TEST(BackendConsistency, MaximumCliqueKeepsTheLargestConsistentSet) {
  const OdometryChain chain = line(200);
  LoopConsistency bounds;
  bounds.translation_per_m = 0.0;
  bounds.rotation_per_m = 0.0;
  ConsistencyGraph graph;
  std::vector<int> good;
  const std::vector<Edge> loops = {
      loop(0, 100, test::planarPose({100.0, 0.0, 0.0}, 0.0)),  // good
      loop(5, 150, test::planarPose({140.0, 8.0, 0.0}, 0.0)),  // bad
      loop(10, 110, test::planarPose({100.0, 0.0, 0.0}, 0.0)),  // good
      loop(20, 120, test::planarPose({100.3, 0.0, 0.0}, 0.0)),  // good, slightly off
      loop(6, 151, test::planarPose({140.0, 8.0, 0.0}, 0.0)),  // bad, like the other bad one
      loop(30, 130, test::planarPose({100.0, 0.0, 0.0}, 0.0)),  // good
      loop(40, 140, test::planarPose({100.0, 0.2, 0.0}, 0.0)),  // good
  };
  for (const Edge& e : loops) graph.add(e, chain, bounds);
  EXPECT_TRUE(graph.adjacent(1, 4));
  EXPECT_FALSE(graph.adjacent(0, 1));
  EXPECT_TRUE(graph.adjacent(0, 3));
  EXPECT_EQ(graph.degree(0), 4);
  EXPECT_EQ(graph.maximumClique(), (std::vector<int>{0, 2, 3, 5, 6}));
  EXPECT_TRUE(ConsistencyGraph{}.maximumClique().empty());
}

}  // namespace
}  // namespace sgtllc::backend
