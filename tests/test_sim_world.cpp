// World generation, route planning, driving and loop pairs: determinism, objects where they belong, a drivable
// trajectory with revisits of every kind, and pairs that agree with the poses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>

#include <Eigen/LU>

#include "sgtllc/sim/loop_pairs.h"
#include "sgtllc/sim/simulator.h"

namespace sgtllc::sim {
namespace {

WorldConfig smallWorld(uint64_t seed, SceneKind kind = SceneKind::kUrban) {
  WorldConfig c;
  c.preset = scenePreset(kind);
  c.seed = seed;
  c.blocks_x = c.blocks_y = 3;
  c.duration = 100.0;
  return c;
}

bool samePrimitive(const Primitive& a, const Primitive& b) {
  return a.shape == b.shape && a.semantic == b.semantic && a.object == b.object && a.centre == b.centre &&
         a.half == b.half && a.cos_yaw == b.cos_yaw && a.sin_yaw == b.sin_yaw &&
         a.mean_free_path == b.mean_free_path && a.t_begin == b.t_begin && a.t_end == b.t_end;
}

TEST(SimWorld, SameSeedSameWorld) {
  const World a = generateWorld(smallWorld(4)), b = generateWorld(smallWorld(4)), c = generateWorld(smallWorld(5));
  ASSERT_EQ(a.statics.size(), b.statics.size());
  for (size_t i = 0; i < a.statics.size(); ++i) {
    ASSERT_TRUE(samePrimitive(a.statics.primitives()[i], b.statics.primitives()[i])) << i;
  }
  EXPECT_EQ(a.agents.size(), b.agents.size());
  EXPECT_NE(a.statics.size(), c.statics.size());
}

TEST(SimWorld, EveryPresetHasItsStructures) {
  for (SceneKind kind : {SceneKind::kUrban, SceneKind::kSuburban, SceneKind::kRural}) {
    const World w = generateWorld(smallWorld(2, kind));
    std::set<uint16_t> labels;
    for (const Primitive& p : w.statics.primitives()) labels.insert(p.semantic);
    for (uint16_t id : {semantic::kVegetation, semantic::kTrunk, semantic::kPole, semantic::kTrafficSign}) {
      EXPECT_TRUE(labels.count(id)) << sceneName(kind) << " lacks " << id;
    }
    if (kind != SceneKind::kRural) {
      EXPECT_TRUE(labels.count(semantic::kBuilding)) << sceneName(kind);
      EXPECT_TRUE(labels.count(semantic::kCar)) << sceneName(kind);
    }
  }
}

TEST(SimWorld, ObjectsStandWhereTheyBelong) {
  const World w = generateWorld(smallWorld(6));
  int buildings = 0, cars = 0;
  for (const Primitive& p : w.statics.primitives()) {
    const Zone zone = w.zones.at(p.centre.x(), p.centre.y());
    if (p.semantic == semantic::kBuilding) {
      ++buildings;
      EXPECT_TRUE(zone == Zone::kLawn || zone == Zone::kPaved) << "building on zone " << static_cast<int>(zone);
    }
    if (p.semantic == semantic::kCar) {
      ++cars;
      EXPECT_EQ(zone, Zone::kParking);
    }
    if (p.semantic == semantic::kTrunk || p.semantic == semantic::kTrafficSign) {
      EXPECT_NE(zone, Zone::kRoad);
    }
  }
  EXPECT_GT(buildings, 50);
  EXPECT_GT(cars, 20);
  // Only vehicles and people carry instance ids.
  for (const Object& o : w.objects) {
    EXPECT_EQ(o.instance != 0, o.kind == ObjectKind::kVehicle || o.kind == ObjectKind::kPerson);
  }
}

TEST(SimWorld, TrajectoryIsDrivable) {
  SimConfig config;
  config.frames = 1500;
  config.seed = 3;
  const Simulator sim(config);
  ASSERT_EQ(sim.numFrames(), 1500);
  const World& w = sim.world();
  int on_road = 0;
  for (int i = 0; i < sim.numFrames(); ++i) {
    const FramePose& f = sim.poses()[i];
    EXPECT_NEAR(f.time, 0.1 * i, 1e-9);
    EXPECT_GE(f.speed, 5.0 - 1e-9);
    EXPECT_LE(f.speed, 15.0 + 1e-9);
    const Eigen::Matrix3d R = f.T_world_lidar.topLeftCorner<3, 3>();
    EXPECT_NEAR(R.determinant(), 1.0, 1e-9);
    EXPECT_GT(R(2, 2), std::cos(6.0 * M_PI / 180.0));  // pitch and roll stay small
    const Eigen::Vector3d x = f.T_world_lidar.topRightCorner<3, 1>();
    EXPECT_NEAR(x.z() - w.ground.height(x.x(), x.y()), 1.73, 0.05);
    const Zone zone = w.zones.at(x.x(), x.y());
    on_road += zone == Zone::kRoad || zone == Zone::kParking;
    if (i > 0) {
      const double step = (x - sim.poses()[i - 1].T_world_lidar.topRightCorner<3, 1>()).norm();
      EXPECT_GT(step, 0.45);
      EXPECT_LT(step, 1.55);
    }
  }
  EXPECT_GT(on_road, 0.97 * sim.numFrames());  // turns may cut a kerb corner
}

TEST(SimWorld, RouteRevisitsEveryKindWithoutUTurns) {
  WorldConfig wc = smallWorld(8);
  wc.blocks_x = wc.blocks_y = 5;
  const World w = generateWorld(wc);
  const std::vector<Leg> legs = planRoute(w.roads, 4000.0, 8, 8);
  std::set<VisitKind> kinds;
  for (size_t i = 0; i < legs.size(); ++i) {
    kinds.insert(legs[i].kind);
    if (i > 0) {
      EXPECT_NE(legs[i].edge, legs[i - 1].edge) << "U-turn at leg " << i;
      const RoadEdge& prev = w.roads.edges()[legs[i - 1].edge];
      const RoadEdge& cur = w.roads.edges()[legs[i].edge];
      EXPECT_EQ(legs[i - 1].forward ? prev.b : prev.a, legs[i].forward ? cur.a : cur.b) << "gap at leg " << i;
    }
    if (isRevisit(legs[i].kind)) {
      const Leg& src = legs[legs[i].source];
      EXPECT_EQ(src.edge, legs[i].edge);
      EXPECT_EQ(src.forward, legs[i].kind != VisitKind::kOppositeDirection ? legs[i].forward : !legs[i].forward);
      if (legs[i].kind == VisitKind::kLaneShift1) {
        EXPECT_GE(std::abs(src.offset - legs[i].offset), 3.3 - 1e-9);
      }
    }
  }
  for (VisitKind k : {VisitKind::kSameDirection, VisitKind::kOppositeDirection, VisitKind::kLaneShift1}) {
    EXPECT_TRUE(kinds.count(k)) << visitKindName(k);
  }
}

TEST(SimWorld, LoopPairsAgreeWithDistances) {
  // A figure of eight: out along x, round a loop, back over the first part in the other direction.
  std::vector<Eigen::Matrix4d> poses;
  for (int i = 0; i < 400; ++i) {
    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    const double a = 2.0 * M_PI * i / 200.0;
    T(0, 3) = 30.0 * std::sin(a);
    T(1, 3) = 15.0 * std::sin(2.0 * a) + (i >= 200 ? 1.0 : 0.0);  // the second lap is 1 m aside
    poses.push_back(T);
  }
  LoopPairOptions o;
  o.seed = 5;
  const std::vector<LoopPair> pairs = loopPairs(poses, o);
  std::set<std::pair<int, int>> listed;
  size_t positives = 0, negatives = 0;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const LoopPair& p = pairs[k];
    const double d = (poses[p.query].topRightCorner<3, 1>() - poses[p.candidate].topRightCorner<3, 1>()).norm();
    EXPECT_GE(p.query - p.candidate, o.min_gap);
    EXPECT_TRUE(p.loop ? d <= 3.0 : d > 20.0) << p.query << " " << p.candidate << " " << d;
    EXPECT_TRUE(listed.insert({p.query, p.candidate}).second);
    if (k > 0) {
      EXPECT_TRUE(pairs[k - 1].query < p.query || pairs[k - 1].candidate < p.candidate);
    }
    ++(p.loop ? positives : negatives);
  }
  size_t expected = 0;
  for (int q = 0; q < 400; ++q) {
    for (int c = 0; c + o.min_gap <= q; ++c) {
      if ((poses[q].topRightCorner<3, 1>() - poses[c].topRightCorner<3, 1>()).norm() <= 3.0) {
        ++expected;
        EXPECT_TRUE(listed.count({q, c}));
      }
    }
  }
  EXPECT_EQ(positives, expected);
  EXPECT_GT(positives, 100u);
  EXPECT_EQ(negatives, positives);
}

}  // namespace
}  // namespace sgtllc::sim
