// Two sessions in one simulated world (docs/relocalization.md): the second keeps the first one's static world and
// frame, draws its own traffic, start and route, and overlaps the first route in part; the manifest that rebuilds a
// first session reads back exactly; the cross-session nearest frames equal a brute-force search.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <tuple>

#include "sgtllc/sim/cross_session.h"
#include "sgtllc/sim/manifest.h"
#include "sgtllc/sim/rng.h"
#include "sgtllc/sim/simulator.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {
namespace {

using ::testing::HasSubstr;

SimConfig firstConfig() {
  SimConfig c;
  c.frames = 1200;
  c.seed = 4;
  return c;
}

SimConfig secondConfig(int frames = 600, uint64_t seed = 9) {
  SimConfig c;
  c.frames = frames;
  c.seed = seed;
  c.world_of = std::make_shared<SimConfig>(firstConfig());
  return c;
}

bool isVehicle(const Primitive& p) {
  return p.semantic == semantic::kCar || p.semantic == semantic::kOtherVehicle || p.semantic == semantic::kTruck;
}

using PrimKey = std::tuple<uint32_t, uint16_t, float, float, float, float, float, float>;

std::vector<PrimKey> keys(const World& w, bool vehicles) {
  std::vector<PrimKey> out;
  for (const Primitive& p : w.statics.primitives()) {
    if (isVehicle(p) != vehicles) continue;
    // Vehicles are keyed by place alone: their object ids follow from how many came before.
    out.emplace_back(vehicles ? 0u : p.object, p.semantic, p.centre.x(), p.centre.y(), p.centre.z(), p.half.x(),
                     p.half.y(), p.half.z());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Eigen::Vector3d> positions(const std::vector<Eigen::Matrix4d>& poses) {
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Matrix4d& T : poses) out.push_back(T.topRightCorner<3, 1>());
  return out;
}

std::vector<Eigen::Matrix4d> worldPoses(const Simulator& s) {
  std::vector<Eigen::Matrix4d> out;
  for (const FramePose& p : s.poses()) out.push_back(p.T_world_lidar);
  return out;
}

class SimSession : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    first_ = new Simulator(firstConfig());
    second_ = new Simulator(secondConfig());
  }
  static void TearDownTestSuite() {
    delete first_;
    delete second_;
  }
  static const Simulator* first_;
  static const Simulator* second_;
};
const Simulator* SimSession::first_ = nullptr;
const Simulator* SimSession::second_ = nullptr;

TEST_F(SimSession, KeepsTheStaticWorldAndFrameButNotTheTraffic) {
  const World &a = first_->world(), &b = second_->world();
  EXPECT_EQ(b.config.seed, a.config.seed);
  EXPECT_EQ(b.config.trafficSeed(), 9u);
  EXPECT_EQ(a.config.trafficSeed(), 4u);
  EXPECT_EQ(keys(a, false), keys(b, false));  // buildings, vegetation, furniture: identical
  const std::vector<PrimKey> ka = keys(a, true), kb = keys(b, true);
  std::vector<PrimKey> common;
  std::set_intersection(ka.begin(), ka.end(), kb.begin(), kb.end(), std::back_inserter(common));
  EXPECT_GT(ka.size(), 100u);
  EXPECT_GT(kb.size(), 100u);
  EXPECT_LT(common.size(), ka.size() / 10);  // parked cars stand elsewhere
  EXPECT_EQ(second_->T_world_origin(), first_->poses()[0].T_world_lidar);
  EXPECT_EQ(second_->firstSessionPoses(), worldPoses(*first_));
  EXPECT_TRUE(second_->isSecondSession());
  EXPECT_EQ(second_->config().plannedRevisits(), 0);
  EXPECT_FALSE(first_->isSecondSession());
  EXPECT_TRUE(first_->firstSessionPoses().empty());
}

TEST_F(SimSession, StartsElsewhereAndDrivesOldAndNewStreets) {
  ASSERT_EQ(second_->numFrames(), 600);
  const Eigen::Vector3d start1 = first_->poses()[0].T_world_lidar.topRightCorner<3, 1>();
  const Eigen::Vector3d start2 = second_->poses()[0].T_world_lidar.topRightCorner<3, 1>();
  EXPECT_GT((start1 - start2).norm(), 100.0);
  const std::vector<NearestFrame> nearest =
      nearestFrames(positions(worldPoses(*first_)), positions(worldPoses(*second_)));
  int near = 0, far = 0;
  for (const NearestFrame& f : nearest) {
    near += f.distance <= 3.0;
    far += f.distance > 20.0;
  }
  EXPECT_GT(near, 600 * 0.3) << near;
  EXPECT_GT(far, 600 * 0.1) << far;
}

TEST_F(SimSession, SameConfigSameSecondSession) {
  const Simulator again(secondConfig());
  EXPECT_EQ(worldPoses(again), worldPoses(*second_));
  const Simulator other(secondConfig(600, 10));
  EXPECT_NE(worldPoses(other), worldPoses(*second_));
}

TEST(SimSessionConfig, RefusesWhatCannotShareAWorld) {
  auto message = [](const SimConfig& c) {
    try {
      c.validate();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  SimConfig c = secondConfig(100, 4);
  EXPECT_THAT(message(c), HasSubstr("seed other than its first session's (4)"));
  c = secondConfig(100);
  c.scene = SceneKind::kRural;
  EXPECT_THAT(message(c), HasSubstr("first session's scene (urban), not rural"));
  c = secondConfig(100);
  SimConfig chained = secondConfig(100, 11);
  chained.world_of = std::make_shared<SimConfig>(c);
  EXPECT_THAT(message(chained), HasSubstr("must not be a second session itself"));
}

TEST_F(SimSession, AFollowingSessionDrivesOnlyTheFirstOnesStreets) {
  // --follow: the same streets again, from where the first session started, either way; a plain second session
  // drives a tenth or more of its frames more than 20 m from every first-session frame (above).
  SimConfig c = secondConfig();
  c.follow = true;
  const Simulator follower(c);
  ASSERT_EQ(follower.numFrames(), 600);
  const std::vector<NearestFrame> nearest =
      nearestFrames(positions(worldPoses(*first_)), positions(worldPoses(follower)));
  int near = 0, far = 0;
  for (const NearestFrame& f : nearest) {
    near += f.distance <= 3.0;
    far += f.distance > 20.0;
  }
  EXPECT_GE(near, 600 * 0.95) << near;
  EXPECT_EQ(far, 0);
  EXPECT_NE(worldPoses(follower), worldPoses(*second_));
  SimConfig alone = firstConfig();
  alone.follow = true;
  EXPECT_THROW(alone.validate(), Error);  // nothing to follow
}

TEST(SimManifest, ReadsBackExactly) {
  SimConfig c = secondConfig(321, 12);
  c.label_noise = 0.1234567890123;
  c.sensor = SensorConfig::preset(SensorKind::kMid70);
  c.accumulate = 7;
  const std::string text = manifestText(c);
  EXPECT_THAT(text, HasSubstr("\nfirst.seed 4\n"));
  const SimConfig r = parseManifest(text, "m.txt");
  EXPECT_EQ(r.frames, 321);
  EXPECT_EQ(r.seed, 12u);
  EXPECT_EQ(r.label_noise, c.label_noise);
  EXPECT_EQ(r.sensor.kind, SensorKind::kMid70);
  EXPECT_EQ(r.accumulate, 7);
  EXPECT_EQ(r.revisits, -1);
  EXPECT_EQ(r.sensor_height, c.sensor_height);
  ASSERT_TRUE(r.world_of);
  EXPECT_EQ(r.world_of->frames, 1200);
  EXPECT_EQ(r.world_of->seed, 4u);
  EXPECT_FALSE(r.world_of->world_of);
  EXPECT_FALSE(parseManifest(manifestText(firstConfig()), "m.txt").world_of);
  EXPECT_FALSE(r.follow);
  EXPECT_THAT(text, ::testing::Not(HasSubstr("follow")));  // manifests written before --follow are unchanged
  c.follow = true;
  EXPECT_THAT(manifestText(c), HasSubstr("\nfollow 1\n"));
  EXPECT_TRUE(parseManifest(manifestText(c), "m.txt").follow);
  EXPECT_THROW(parseManifest(manifestText(c) + "follow 1\n", "m.txt"), Error);  // twice
  std::string two = manifestText(c);
  two.replace(two.find("follow 1"), 8, "follow 2");
  EXPECT_THROW(parseManifest(two, "m.txt"), Error);
}

TEST(SimManifest, BadManifestsAreNamed) {
  const std::string good = manifestText(firstConfig());
  auto message = [](const std::string& text) {
    try {
      parseManifest(text, "S1/simulation.txt");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  EXPECT_EQ(message(replaced("format 1", "format 2")),
            "S1/simulation.txt: format 2 is newer than this sgtllc reads (1); use a newer sgtllc");
  EXPECT_EQ(message(replaced("scene urban", "scene downtown")),
            "S1/simulation.txt: line 5: 'downtown' is not a valid scene");
  EXPECT_EQ(message(replaced("seed 4", "seed -4")), "S1/simulation.txt: line 4: '-4' is not a valid seed");
  EXPECT_EQ(message(replaced("frames 1200\n", "")), "S1/simulation.txt: 'frames' is missing");
  EXPECT_EQ(message(good + "colour red\n"), "S1/simulation.txt: line 11: unknown key 'colour'");
  EXPECT_EQ(message(good + "seed 5\n"), "S1/simulation.txt: line 11: 'seed' appears twice");
  EXPECT_EQ(message(replaced("frames 1200", "frames 0")),
            "S1/simulation.txt: frames must be 1..1000000, not 0");
  EXPECT_THAT(message("garbage"), HasSubstr("line 1: expected 'key value'"));
}

TEST(SimManifest, AFolderWithoutOneSaysWhy) {
  try {
    readManifest(SGTLLC_DATA_DIR);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("has no simulation.txt"));
    EXPECT_THAT(e.what(), HasSubstr("older than the manifest"));
  }
}

TEST(SimCrossSession, NearestFramesEqualBruteForce) {
  Rng rng(3);
  std::vector<Eigen::Vector3d> map, queries;
  for (int i = 0; i < 400; ++i) {
    const double x = std::round(rng.uniform(-200, 200)), y = std::round(rng.uniform(-50, 50));
    map.emplace_back(x, y, 0.0);  // integer coordinates: many exact ties
  }
  map.push_back(map[17]);  // a duplicate: the lower index wins
  for (int i = 0; i < 300; ++i) {
    const double x = std::round(rng.uniform(-400, 400)), y = std::round(rng.uniform(-100, 100));
    queries.emplace_back(x, y, std::round(rng.uniform(-3, 3)));
  }
  queries.push_back(map[17]);
  const std::vector<NearestFrame> got = nearestFrames(map, queries, 7.0);
  for (size_t q = 0; q < queries.size(); ++q) {
    int best = -1;
    double best_d = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < map.size(); ++i) {
      const double d = (map[i] - queries[q]).norm();
      if (d < best_d) {
        best_d = d;
        best = static_cast<int>(i);
      }
    }
    ASSERT_EQ(got[q].frame, best) << q;
    ASSERT_EQ(got[q].distance, best_d) << q;
  }
  EXPECT_EQ(got.back().frame, 17);
  EXPECT_EQ(nearestFrames({}, queries).front().frame, -1);
  EXPECT_THROW(nearestFrames(map, queries, 0.0), Error);
}

}  // namespace
}  // namespace sgtllc::sim
