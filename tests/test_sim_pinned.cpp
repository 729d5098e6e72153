// Pinned worlds: the same seed must give the same world with every conforming compiler. C++ leaves the order of
// function arguments and operands unspecified, so two random draws in one expression are drawn in a different order
// by GCC and clang (include/sgtllc/sim/rng.h). A same-binary determinism test cannot see that; these fixed
// reference values, taken from the GCC 12 build, fail under any compiler that builds another world.
//
// Counts are exact; the checksums are weighted sums compared with a relative tolerance, so last-bit rounding
// (another libm, FMA contraction) passes while a shuffled draw (another object, another size) does not.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "sgtllc/sim/simulator.h"

namespace sgtllc::sim {
namespace {

struct Summary {
  size_t nodes = 0, edges = 0, primitives = 0, objects = 0, agents = 0;
  double roads = 0.0, geometry = 0.0, appearance = 0.0, motion = 0.0;
};

/// Weight by position in the list, so swapping two values changes the sum.
double weight(size_t i) { return 1.0 + static_cast<double>(i % 97) / 97.0; }

Summary summarise(uint64_t seed, SceneKind kind) {
  WorldConfig c;
  c.preset = scenePreset(kind);
  c.seed = seed;
  c.blocks_x = c.blocks_y = 3;
  c.duration = 100.0;
  const World w = generateWorld(c);
  Summary s;
  s.nodes = w.roads.nodes().size();
  s.edges = w.roads.edges().size();
  s.primitives = w.statics.size();
  s.objects = w.objects.size();
  s.agents = w.agents.size();
  for (size_t i = 0; i < w.roads.nodes().size(); ++i) {
    const Eigen::Vector2d& p = w.roads.nodes()[i].p;
    s.roads += weight(i) * (p.x() + 2.0 * p.y());
  }
  for (size_t i = 0; i < w.roads.edges().size(); ++i) s.roads += weight(i) * w.roads.edges()[i].length();
  const auto& prims = w.statics.primitives();
  for (size_t i = 0; i < prims.size(); ++i) {
    const Primitive& p = prims[i];
    s.geometry += weight(i) * (p.centre.x() + 2.0 * p.centre.y() + 3.0 * p.centre.z() + 5.0 * p.half.x() +
                               7.0 * p.half.y() + 11.0 * p.half.z() + 13.0 * p.cos_yaw + 17.0 * p.sin_yaw);
    s.appearance += weight(i) * (p.semantic + p.object + 10.0 * p.mean_free_path + 10.0 * p.reflectivity +
                                 (std::isfinite(p.t_begin) ? p.t_begin : -1.0) +
                                 (std::isfinite(p.t_end) ? 2.0 * p.t_end : -2.0));
  }
  for (size_t i = 0; i < w.agents.size(); ++i) {
    const Agent& a = w.agents[i];
    s.motion += weight(i) * (a.edge + (a.forward ? 1.0 : 0.0) + 2.0 * a.offset + 3.0 * a.speed + 5.0 * a.phase +
                             7.0 * a.length + 11.0 * a.width + 13.0 * a.height);
  }
  return s;
}

void expectSummary(const Summary& got, const Summary& want) {
  EXPECT_EQ(got.nodes, want.nodes);
  EXPECT_EQ(got.edges, want.edges);
  EXPECT_EQ(got.primitives, want.primitives);
  EXPECT_EQ(got.objects, want.objects);
  EXPECT_EQ(got.agents, want.agents);
  for (const auto& [g, e] : {std::pair{got.roads, want.roads}, std::pair{got.geometry, want.geometry},
                             std::pair{got.appearance, want.appearance}, std::pair{got.motion, want.motion}}) {
    EXPECT_NEAR(g, e, 1e-6 * std::abs(e));
  }
}

TEST(SimPinned, UrbanSeed4) { expectSummary(summarise(4, SceneKind::kUrban), {16, 23, 1789, 885, 31, 8842.2086781269736, 1133475.5620019988, 1407233.0476878053, 9503.9039483041397}); }
TEST(SimPinned, SuburbanSeed5) { expectSummary(summarise(5, SceneKind::kSuburban), {16, 24, 3165, 1410, 42, 13766.378233422589, 3001012.8121586111, 3936383.9936254094, 21261.15439522119}); }
TEST(SimPinned, RuralSeed3) { expectSummary(summarise(3, SceneKind::kRural), {16, 20, 4495, 1807, 16, 28474.64983372085, 10664206.884659246, 6877891.3610809883, 16361.868753369385}); }

}  // namespace
}  // namespace sgtllc::sim
