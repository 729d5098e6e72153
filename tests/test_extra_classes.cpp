// Extra classes beyond the paper's seven (labels.extra_classes): label mapping, node files, extraction, graph and
// descriptors against brute-force references at C = 8, 9 and 16, the embedding of a seven-class frame into a larger
// class set, and a revisit that only the vehicles make.
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sgtllc/detector.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/ply.h"
#include "sgtllc/node_extraction.h"
#include "test_cli_support.h"
#include "test_graph_support.h"
#include "test_io_support.h"
#include "test_kitti_support.h"

namespace sgtllc {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::ThrowsMessage;

constexpr int kVehicle = kNumPaperClasses;  // the first extra class

/// The paper's classes plus `vehicle`: SemanticKITTI car, bicycle, motorcycle, truck, other-vehicle and their
/// moving variants.
Config vehicleConfig() {
  Config c;
  c.addClass({"vehicle", {10, 13, 18, 20, 252, 256, 257, 258, 259}}, {0.0, 1.0, 20});
  return c;
}

TEST(ExtraClasses, ConfigDeclaresTheClassAndItsParameters) {
  const Config c = vehicleConfig();
  EXPECT_EQ(c.numClasses(), 8);
  EXPECT_EQ(c.labels.className(kVehicle), "vehicle");
  EXPECT_EQ(c.labels.className(kPole), "pole");
  EXPECT_EQ(c.cluster.classes.size(), 8u);
  EXPECT_NO_THROW(c.validate());
  EXPECT_EQ(Config{}.numClasses(), 7);
}

TEST(ExtraClasses, LabelMapSendsDeclaredIdsToTheExtraClass) {
  const LabelMap map(vehicleConfig().labels);
  for (uint32_t id : {10u, 13u, 252u, 259u, 10u | (5u << 16)}) EXPECT_EQ(map.classOf(id), kVehicle) << id;
  EXPECT_EQ(map.classOf(50), kBuilding);
  EXPECT_EQ(map.classOf(81), kTrafficSign);
  EXPECT_EQ(map.classOf(40), kDropped);  // road stays dropped
  EXPECT_EQ(LabelMap().classOf(10), kDropped);

  // Another preset: SemanticKITTI learning ids (car = 1); a new id becomes known.
  LabelConfig learning;
  learning.preset = LabelPreset::kSemanticKittiLearning;
  learning.extra_classes = {{"car", {1}}, {"thing", {1000}}};
  const LabelMap lm(learning);
  EXPECT_EQ(lm.classOf(1), 7);
  EXPECT_EQ(lm.classOf(13), kBuilding);
  EXPECT_EQ(lm.classOf(1000), 8);
  EXPECT_TRUE(lm.isKnown(1000));

  // Preset custom: custom_map may target an extra class that lists no ids.
  Config custom;
  custom.labels.preset = LabelPreset::kCustom;
  custom.labels.custom_map = {{5, 0}, {6, 7}};
  custom.addClass({"vehicle", {}});
  EXPECT_NO_THROW(custom.validate());
  EXPECT_EQ(LabelMap(custom.labels).classOf(6), kVehicle);
}

class ExtraClassFiles : public test::TempDirTest {};

TEST_F(ExtraClassFiles, NodeFileCarRowsBecomeVehicleNodes) {
  const std::string p = path("nodes.txt");
  std::ofstream(p) << "1 2 0 50\n3 4 0 10\n5 6 0 80\n7 8 0 252\n9 9 0 40\n";
  io::NodeFileStats stats;
  const std::vector<Node> plain = io::readNodesTxt(p, LabelMap(), &stats);
  ASSERT_EQ(plain.size(), 2u);  // building, pole
  EXPECT_EQ(stats.dropped_known, 3u);

  const Config config = vehicleConfig();
  const std::vector<Node> nodes = io::readNodesTxt(p, LabelMap(config.labels), &stats);
  ASSERT_EQ(nodes.size(), 4u);
  EXPECT_EQ(stats.dropped_known, 1u);  // road
  const std::vector<int> labels = {nodes[0].label, nodes[1].label, nodes[2].label, nodes[3].label};
  EXPECT_EQ(labels, (std::vector<int>{kBuilding, kVehicle, kPole, kVehicle}));
  EXPECT_EQ(nodes[1].centre, Eigen::Vector3d(3, 4, 0));

  // Written back with the class's first id (10), read back the same.
  const std::string q = path("back.txt");
  io::writeNodesTxt(q, nodes, config.labels);
  std::ifstream in(q);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("\n7 8 0 10\n"));
  const std::vector<Node> back = io::readNodesTxt(q, LabelMap(config.labels));
  ASSERT_EQ(back.size(), nodes.size());
  for (size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].label, nodes[i].label);
    EXPECT_EQ(back[i].centre, nodes[i].centre);
  }
  // Without the class, label 7 is no class of the configuration.
  EXPECT_THAT([&] { io::writeNodesTxt(q, nodes); }, ThrowsMessage<Error>(HasSubstr("node 1 has label 7, not a stable "
                                                                                   "class index 0..6")));
}

TEST_F(ExtraClassFiles, PlyColoursAreDistinctForEveryClass) {
  std::set<std::array<uint8_t, 3>> colours;
  for (int c = 0; c < kMaxClasses; ++c) colours.insert(io::classColor(c, kMaxClasses));
  EXPECT_EQ(colours.size(), static_cast<size_t>(kMaxClasses));
  EXPECT_EQ(io::classColor(kVehicle, 8), (std::array<uint8_t, 3>{100, 150, 245}));
  EXPECT_EQ(io::classColor(kPole, 8), io::classColor(kPole));  // the seven keep their colours
  EXPECT_THROW(io::classColor(kVehicle), Error);
  EXPECT_THROW(io::classColor(8, 8), Error);

  const std::string p = path("g.ply");
  io::writeGraphPly(p, {test::node(0, 0, 0, kVehicle)}, {}, 8);
  std::ifstream in(p);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_THAT(text, HasSubstr("\n0 0 0 100 150 245 7\n"));
  EXPECT_THROW(io::writeGraphPly(path("h.ply"), {test::node(0, 0, 0, kVehicle)}, {}), Error);
}

// --- Extraction --------------------------------------------------------------------------------------------------

/// @p count points with id @p id in a 0.5 m cube at @p centre (FEC radius 1 m joins them).
void addBlob(LabeledCloud& cloud, const Eigen::Vector3f& centre, int count, uint32_t id, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-0.25f, 0.25f);
  for (int i = 0; i < count; ++i) {
    const float x = u(rng), y = u(rng), z = u(rng);
    cloud.points.push_back(centre + Eigen::Vector3f(x, y, z));
    cloud.labels.push_back(id);
  }
}

TEST(ExtraClasses, ExtractionClustersVehiclesWithTheirOwnParameters) {
  std::mt19937 rng(3);
  LabeledCloud cloud;
  addBlob(cloud, {10, 0, 0}, 30, 10, rng);   // car
  addBlob(cloud, {20, 0, 0}, 40, 252, rng);  // moving car
  addBlob(cloud, {30, 0, 0}, 8, 18, rng);    // truck, small
  addBlob(cloud, {0, 10, 0}, 25, 80, rng);   // pole

  const NodeExtractionResult plain = NodeExtractor(Config{}.cluster, Config{}.labels).extract(cloud);
  ASSERT_EQ(plain.nodes.size(), 1u);
  EXPECT_EQ(plain.nodes[0].label, kPole);

  Config config = vehicleConfig();
  const NodeExtractionResult r = NodeExtractor(config.cluster, config.labels).extract(cloud);
  EXPECT_EQ(r.stats.class_points[kVehicle], 78u);
  EXPECT_EQ(r.stats.clusters[kVehicle], 2);  // min_size 20 drops the truck
  ASSERT_EQ(r.nodes.size(), 3u);
  EXPECT_EQ(r.nodes[0].label, kPole);  // class order: the seven first
  EXPECT_EQ(r.nodes[1].label, kVehicle);
  EXPECT_NEAR(r.nodes[1].centre.x(), 10.0, 0.1);
  EXPECT_NEAR(r.nodes[2].centre.x(), 20.0, 0.1);

  config.cluster.classes[kVehicle].min_size = 5;
  EXPECT_EQ(NodeExtractor(config.cluster, config.labels).extract(cloud).nodes.size(), 4u);

  config.cluster.classes.pop_back();  // parameters for 7 classes, 8 declared
  EXPECT_THAT([&] { NodeExtractor(config.cluster, config.labels); },
              ThrowsMessage<Error>(HasSubstr("cluster parameters for 7 classes, but 8 classes")));
}

TEST(ExtraClasses, RealKittiScanKeepsItsSevenClassNodesAndAddsVehicles) {
  const LabeledCloud scan = test::kittiScan("004501");
  const std::vector<Node> plain = NodeExtractor(Config{}.cluster, Config{}.labels).extract(scan).nodes;
  const Config config = vehicleConfig();
  const std::vector<Node> nodes = NodeExtractor(config.cluster, config.labels).extract(scan).nodes;
  ASSERT_GT(nodes.size(), plain.size());
  for (size_t i = 0; i < plain.size(); ++i) {  // the same nodes first, in the same order
    ASSERT_EQ(nodes[i].label, plain[i].label) << i;
    ASSERT_EQ(nodes[i].centre, plain[i].centre) << i;
  }
  for (size_t i = plain.size(); i < nodes.size(); ++i) EXPECT_EQ(nodes[i].label, kVehicle) << i;
}

// --- Graph and descriptors ---------------------------------------------------------------------------------------

TEST(ExtraClasses, GraphAndLocalDescriptorsMatchBruteForceForLargerClassSets) {
  for (int classes : {8, 9, kMaxClasses}) {
    for (uint32_t seed : {1u, 2u}) {
      const std::vector<Node> nodes = test::randomNodes(seed, 60, seed == 2, classes);
      const SemanticGraph g = buildGraph(nodes, GraphConfig{}, classes);
      ASSERT_EQ(g.numSlots(), classes * classes);
      const test::RefGraph ref = test::bruteGraph(nodes, 30.0, false, classes);
      const std::vector<LocalDescriptor> des = computeLocalDescriptors(g, {});
      int valid = 0;
      for (int i = 0; i < g.size(); ++i) {
        ASSERT_EQ(des[i].numSlots(), classes * classes);
        ASSERT_EQ(des[i].flat().size(), static_cast<size_t>(3 * classes * classes));
        for (int s = 0; s < g.numSlots(); ++s) {
          const auto [j, k] = ref.paths[i][s];
          ASSERT_EQ(std::make_pair(g.paths[i][s].j, g.paths[i][s].k), ref.paths[i][s]) << classes << " " << i;
          ASSERT_EQ(des[i].isValid(s), j >= 0);
          const Eigen::Vector3f want = j < 0 ? Eigen::Vector3f::Zero()
                                             : test::terms(nodes[i].centre, nodes[j].centre, nodes[k].centre)
                                                   .cast<float>()
                                                   .eval();
          ASSERT_EQ(des[i].slots[s], want);
          valid += j >= 0;
        }
        EXPECT_EQ(des[i].numValid(), static_cast<int>(std::count_if(
                                         ref.paths[i].begin(), ref.paths[i].end(), [](auto p) { return p.first >= 0; })));
      }
      EXPECT_GT(valid, 0);
    }
  }
  // Slot 255 of 16 classes lies in the last word of the mask.
  const std::vector<Node> two = {test::node(0, 0, 0, 15), test::node(5, 0, 0, 15), test::node(0, 5, 0, 15)};
  const auto des = computeLocalDescriptors(buildGraph(two, GraphConfig{}, 16), {});
  EXPECT_TRUE(des[0].isValid(255));
  EXPECT_EQ(des[0].valid.words[3], uint64_t{1} << 63);
  EXPECT_EQ(des[0].numValid(), 1);
}

TEST(ExtraClasses, GlobalDescriptorSizeFollowsTheClassCount) {
  EXPECT_EQ(globalDescriptorSize(GlobalMode::kG1), 98);
  EXPECT_EQ(globalDescriptorSize(GlobalMode::kG2), 343);
  EXPECT_EQ(globalDescriptorSize(GlobalMode::kG3, 8), 128);
  EXPECT_EQ(globalDescriptorSize(GlobalMode::kG2, 8), 512);
  EXPECT_EQ(globalDescriptorSize(GlobalMode::kG1, 16), 512);
  EXPECT_EQ(globalDescriptorSize(GlobalMode::kG2, 16), 4096);
  const std::vector<Node> nodes = test::randomNodes(4, 30, false, 8);
  for (GlobalMode mode : {GlobalMode::kG1, GlobalMode::kG2, GlobalMode::kG3}) {
    DescriptorConfig d;
    d.global_mode = mode;
    EXPECT_EQ(describeFrame(nodes, GraphConfig{}, d, true, 8).global.size(),
              static_cast<size_t>(globalDescriptorSize(mode, 8)));
  }
  EXPECT_THROW(buildGraph(nodes, GraphConfig{}), Error);  // labels 7 with the seven classes
}

// A frame of the seven classes described within a larger class set holds the same values, at the cells the larger
// layout gives them, and nothing else.
TEST(ExtraClasses, SevenClassFrameEmbedsInALargerClassSet) {
  const std::vector<Node> nodes = test::randomNodes(5, 40, false);
  constexpr int C = 11;
  for (GlobalMode mode : {GlobalMode::kG1, GlobalMode::kG2, GlobalMode::kG3}) {
    DescriptorConfig d;
    d.global_mode = mode;
    const DescribedFrame small = describeFrame(nodes, GraphConfig{}, d);
    const DescribedFrame big = describeFrame(nodes, GraphConfig{}, d, true, C);
    for (int i = 0; i < small.numNodes(); ++i) {
      EXPECT_EQ(big.local[i].numValid(), small.local[i].numValid());
      for (int m = 0; m < 7; ++m) {
        for (int n = 0; n < 7; ++n) {
          ASSERT_EQ(big.local[i].isValid(C * m + n), small.local[i].isValid(7 * m + n));
          ASSERT_EQ(big.local[i].slots[C * m + n], small.local[i].slots[7 * m + n]);
        }
      }
    }
    std::vector<float> expected(big.global.size(), 0.0f);
    for (size_t cell = 0; cell < small.global.size(); ++cell) {
      const int c = static_cast<int>(cell);
      const size_t to = mode == GlobalMode::kG2 ? C * C * (c / 49) + C * (c % 49 / 7) + c % 7
                                                : 2 * C * (c / 14) + C * (c % 14 / 7) + c % 7;
      expected[to] = small.global[cell];
    }
    EXPECT_EQ(big.global, expected);
  }
}

// --- A revisit made by the vehicles ------------------------------------------------------------------------------

/// A street: 4 poles and 14 parked cars (raw SemanticKITTI ids 80 and 10) in the match frame.
std::vector<std::pair<Eigen::Vector3d, uint32_t>> street() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(-25.0, 25.0), y(-12.0, 12.0);
  std::vector<std::pair<Eigen::Vector3d, uint32_t>> objects;
  for (int k = 0; k < 18; ++k) {
    const double px = x(rng), py = y(rng);
    objects.push_back({Eigen::Vector3d(px, py, k < 4 ? 1.5 : 0.8), k < 4 ? 80u : 10u});
  }
  return objects;
}

class VehicleRevisit : public test::TempDirTest {
 protected:
  /// Writes the street in the match frame and, moved by T_query_match = T_match_query⁻¹, in the query frame.
  void SetUp() override {
    test::TempDirTest::SetUp();
    T_match_query_ = test::rigid(35.0, 1.0, -2.0, Eigen::Vector3d(4.0, -2.5, 0.3));
    const Eigen::Matrix4d T_query_match = T_match_query_.inverse();
    std::ofstream match(path("match.txt")), query(path("query.txt"));
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(0.0, 0.03);
    for (const auto& [p, id] : street()) {
      const Eigen::Vector3d q = T_query_match.topLeftCorner<3, 3>() * p + T_query_match.topRightCorner<3, 1>();
      match << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << id << '\n';
      const double nx = noise(rng), ny = noise(rng), nz = noise(rng);
      query << q.x() + nx << ' ' << q.y() + ny << ' ' << q.z() + nz << ' ' << id << '\n';
    }
  }

  PairResult compare(const Config& config) {
    const LabelMap labels(config.labels);
    return comparePair(io::readNodesTxt(path("query.txt"), labels), io::readNodesTxt(path("match.txt"), labels),
                       config);
  }

  Eigen::Matrix4d T_match_query_;
};

TEST_F(VehicleRevisit, TooFewNodesWithoutVehiclesALoopWithThem) {
  const PairResult plain = compare(Config{});
  EXPECT_EQ(plain.query_nodes.size(), 4u);
  EXPECT_FALSE(plain.is_loop);
  // 4 poles: with the paper's gates |LA| < 7; with the defaults (|LA| ≥ 3) no 3-inlier hypothesis verifies.
  EXPECT_EQ(plain.match.rejection, Rejection::kRansacFailed);

  const PairResult r = compare(vehicleConfig());
  EXPECT_EQ(r.query_nodes.size(), 18u);
  ASSERT_TRUE(r.is_loop);
  EXPECT_GE(r.match.inliers.size(), 14u);
  const test::PoseError e = test::poseError(r.match.T_match_query, T_match_query_);
  EXPECT_LT(e.translation_m, 0.1);
  EXPECT_LT(e.rotation_deg, 0.5);
  int vehicles = 0;
  for (const NodeMatch& a : r.match.associations) vehicles += r.query_nodes[a.query].label == kVehicle;
  EXPECT_GE(vehicles, 10);
}

TEST_F(VehicleRevisit, DetectorStoresRetrievalKeysOfTheLargerSize) {
  // The default key, the distance histogram, and G2: both grow with the eighth class, and both find the loop.
  for (RetrievalKey key : {RetrievalKey::kDistanceHistogram, RetrievalKey::kGlobalDescriptor}) {
    Config config = vehicleConfig();
    config.retrieval.exclude_recent = 1;
    config.retrieval.key = key;
    LoopDetector detector(config);
    const LabelMap labels(config.labels);
    detector.process(io::readNodesTxt(path("match.txt"), labels));
    const FrameResult r = detector.process(io::readNodesTxt(path("query.txt"), labels));
    // Histogram: 36 class pairs × 30 bins; G2, C = 8: 8³.
    EXPECT_EQ(detector.database().globalDimension(), key == RetrievalKey::kGlobalDescriptor ? 512 : 1080);
    ASSERT_TRUE(r.is_loop);
    EXPECT_EQ(r.loop()->frame, 0);
  }
}

TEST_F(VehicleRevisit, PairJsonNamesTheVehicleMatches) {
  std::ofstream(path("vehicle.yaml")) << "labels:\n  extra_classes:\n    - {name: vehicle, ids: [10, 252]}\n"
                                      << "cluster:\n  vehicle: {voxel: 0.0, radius: 1.0, min_size: 20}\n";
  const std::string files = path("query.txt") + " " + path("match.txt");
  const test::CliRun with = test::run("pair " + files + " --json --config " + path("vehicle.yaml"), false);
  ASSERT_EQ(with.status, 0) << with.out;
  EXPECT_THAT(with.out, HasSubstr("\"loop\": true"));
  EXPECT_THAT(with.out, HasSubstr("\"class\": \"vehicle\""));
  EXPECT_THAT(with.out, HasSubstr("\"class\": \"pole\""));
  const test::CliRun without = test::run("pair " + files + " --json", false);
  ASSERT_EQ(without.status, 0) << without.out;
  EXPECT_THAT(without.out, HasSubstr("\"loop\": false"));
  EXPECT_THAT(without.out, Not(HasSubstr("vehicle")));
}

}  // namespace
}  // namespace sgtllc
