// Scan accumulation (BENCHMARKS.md, "Accumulating solid-state scans"): hand-computed merges, the bounded buffer, the simulator's own accumulation, and
// an accumulating FrameSource streamed at 1 and 2 threads.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "sgtllc/accumulate/scan_accumulator.h"
#include "sgtllc/detector.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/io/trajectory.h"
#include "sgtllc/sim/sequence_writer.h"
#include "sgtllc/sim/simulator.h"

namespace sgtllc {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

Eigen::Isometry3d pose(double yaw_deg, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = t;
  return T;
}

LabeledCloud cloud(std::vector<Eigen::Vector3f> points, std::vector<uint32_t> labels) {
  return LabeledCloud{std::move(points), std::move(labels)};
}

void expectPoint(const Eigen::Vector3f& got, float x, float y, float z) {
  EXPECT_NEAR(got.x(), x, 1e-5f);
  EXPECT_NEAR(got.y(), y, 1e-5f);
  EXPECT_NEAR(got.z(), z, 1e-5f);
}

TEST(MergeScans, MovesEachScanIntoTheNewestFrameByHand) {
  // Scan 0 at (1, 0, 0) facing +x; scan 1 at (0, 2, 0) turned 90° left; scan 2 (newest) at (0, 2, 1) turned 180°.
  const LabeledCloud s0 = cloud({{1, 0, 0}, {0, 0, 3}}, {10, 11});
  const LabeledCloud s1 = cloud({{1, 1, 0}}, {20});
  const LabeledCloud s2 = cloud({{5, -4, 2}}, {30});
  const std::vector<Eigen::Isometry3d> T = {pose(0, {1, 0, 0}), pose(90, {0, 2, 0}), pose(180, {0, 2, 1})};
  const LabeledCloud m = mergeScans({&s0, &s1, &s2}, T);
  ASSERT_EQ(m.points.size(), 4u);
  // World → frame 2: p2 = Rz(180)ᵀ (w − (0, 2, 1)) = (−(wx), −(wy − 2), wz − 1).
  // s0 (1,0,0): world (2,0,0) → (−2, 2, −1). s0 (0,0,3): world (1,0,3) → (−1, 2, 2).
  expectPoint(m.points[0], -2, 2, -1);
  expectPoint(m.points[1], -1, 2, 2);
  // s1 (1,1,0): world Rz(90)(1,1,0) + (0,2,0) = (−1, 3, 0) → (1, −1, −1).
  expectPoint(m.points[2], 1, -1, -1);
  EXPECT_EQ(m.points[3], Eigen::Vector3f(5, -4, 2));  // the newest scan as it is, bit for bit
  EXPECT_EQ(m.labels, (std::vector<uint32_t>{10, 11, 20, 30}));  // each label with its point
}

TEST(MergeScans, RefusesMismatchedInput) {
  const LabeledCloud good = cloud({{1, 0, 0}}, {1});
  const LabeledCloud bad = cloud({{1, 0, 0}, {2, 0, 0}}, {1});
  const Eigen::Isometry3d I = Eigen::Isometry3d::Identity();
  EXPECT_THAT([&] { mergeScans({&good, &bad}, {I, I}); }, ThrowsMessage<Error>(HasSubstr("has 2 points but 1 labels")));
  EXPECT_THAT([&] { mergeScans({&good}, {I, I}); }, ThrowsMessage<Error>(HasSubstr("1 scans with 2 poses")));
  Eigen::Isometry3d nan = I;
  nan.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT([&] { mergeScans({&good, &good}, {nan, I}); }, ThrowsMessage<Error>(HasSubstr("not finite")));
  EXPECT_TRUE(mergeScans({}, {}).points.empty());
}

TEST(ScanAccumulator, NeverHoldsMoreThanNScans) {
  ScanAccumulator buffer(4);
  std::vector<size_t> sizes;
  for (int k = 0; k < 11; ++k) {
    // Scan k has k + 1 points, all labelled k, taken 1 m further along x.
    LabeledCloud scan;
    for (int p = 0; p <= k; ++p) {
      scan.points.emplace_back(static_cast<float>(p), 0.0f, 0.0f);
      scan.labels.push_back(static_cast<uint32_t>(k));
    }
    sizes.push_back(scan.points.size());
    const LabeledCloud merged = buffer.add(std::move(scan), pose(0, {static_cast<double>(k), 0, 0}));
    const size_t held = std::min<size_t>(k + 1, 4);
    ASSERT_EQ(buffer.size(), held);
    size_t expected = 0;
    for (size_t j = sizes.size() - held; j < sizes.size(); ++j) expected += sizes[j];
    EXPECT_EQ(merged.points.size(), expected) << k;
    EXPECT_EQ(buffer.points(), expected);
    EXPECT_EQ(buffer.bytes(), 16 * expected);
    // The oldest scan held is k − held + 1, moved back by its distance: its first point lands at x = −(held − 1).
    EXPECT_EQ(merged.labels.front(), static_cast<uint32_t>(k + 1 - static_cast<int>(held)));
    EXPECT_FLOAT_EQ(merged.points.front().x(), -static_cast<float>(held - 1));
  }
  buffer.clear();
  EXPECT_EQ(buffer.size(), 0u);
}

TEST(ScanAccumulator, RefusesBadSizesAndKeepsItsScansOnBadInput) {
  EXPECT_THAT([] { ScanAccumulator(0); }, ThrowsMessage<Error>(HasSubstr("must be 1..1000, not 0")));
  EXPECT_THROW(ScanAccumulator(1001), Error);
  ScanAccumulator buffer(2);
  buffer.add(cloud({{1, 0, 0}}, {1}), Eigen::Isometry3d::Identity());
  EXPECT_THROW(buffer.add(cloud({{1, 0, 0}}, {}), Eigen::Isometry3d::Identity()), Error);
  EXPECT_EQ(buffer.size(), 1u);
  // N = 1: every frame as it is.
  ScanAccumulator single(1);
  single.add(cloud({{1, 0, 0}}, {1}), pose(0, {5, 0, 0}));
  const LabeledCloud m = single.add(cloud({{2, 0, 0}}, {2}), pose(30, {7, 0, 0}));
  EXPECT_EQ(m.points, std::vector<Eigen::Vector3f>{Eigen::Vector3f(2, 0, 0)});
}

/// A small simulated sequence (low-resolution sensor, so it is quick) with 6 scans per frame.
sim::SimConfig smallConfig(int accumulate) {
  sim::SimConfig c;
  c.frames = 15;
  c.seed = 31;
  c.sensor.rows = 16;
  c.sensor.columns = 256;
  c.accumulate = accumulate;
  return c;
}

TEST(ScanAccumulator, EqualsTheSimulatorsOwnAccumulation) {
  const sim::Simulator sim(smallConfig(6));
  ScanAccumulator buffer(6);
  for (int i = 0; i < sim.numFrames(); ++i) {
    const sim::SimScan s = sim.scan(i);
    const LabeledCloud merged =
        buffer.add(cloud(s.points, s.labels), Eigen::Isometry3d(sim.poses()[static_cast<size_t>(i)].T_world_lidar));
    const sim::SimFrame f = sim.frame(i);
    ASSERT_EQ(merged.points, f.points) << "frame " << i;  // bit for bit
    ASSERT_EQ(merged.labels, f.labels) << "frame " << i;
  }
}

class AccumulatingSource : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("sgtllc_accumulate_" + std::string(::testing::UnitTest::GetInstance()
                                                                              ->current_test_info()->name()) +
                                         "_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    for (int n : {1, 6}) {
      sim::WriteOptions o;
      o.dir = (root_ / ("acc" + std::to_string(n))).string();
      o.previews = false;
      o.node_stats_every = 0;
      sim::writeSequence(sim::Simulator(smallConfig(n)), o);
    }
  }
  void TearDown() override { fs::remove_all(root_); }
  std::string dir(int n) const { return (root_ / ("acc" + std::to_string(n))).string(); }

  /// Nodes of every frame as the detector stores them.
  static std::vector<std::vector<Node>> streamed(const pipeline::FrameSource& source, const Config& config, int threads,
                                                 size_t* max_bytes) {
    LoopDetector detector(config);
    std::vector<std::vector<Node>> nodes;
    pipeline::streamSequence(source, detector, threads, [&](size_t i, const pipeline::LoadedFrame& f, const FrameResult&) {
      nodes.push_back(detector.database().nodes(static_cast<int>(i)));
      if (max_bytes) *max_bytes = std::max(*max_bytes, f.buffer_bytes);
    });
    return nodes;
  }

  fs::path root_;
};

void expectSameNodes(const std::vector<Node>& a, const std::vector<Node>& b, size_t frame) {
  ASSERT_EQ(a.size(), b.size()) << "frame " << frame;
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].label, b[k].label) << "frame " << frame;
    EXPECT_LT((a[k].centre - b[k].centre).norm(), 1e-4) << "frame " << frame;
  }
}

TEST_F(AccumulatingSource, MatchesTheWrittenAccumulationAtAnyThreadCount) {
  // The un-accumulated drive, accumulated from its poses.txt + calib.txt, against the simulator's 6-scan files.
  const Config config;
  pipeline::FrameSource raw = pipeline::FrameSource::semanticKitti(dir(1), config);
  const io::Trajectory truth = io::readTrajectory(dir(1) + "/poses.txt", dir(1) + "/calib.txt");
  raw.accumulate(6, truth.poses);
  EXPECT_EQ(raw.accumulated(), 6);
  size_t max_bytes = 0;
  const auto one = streamed(raw, config, 1, &max_bytes);
  const auto two = streamed(raw, config, 2, nullptr);
  const auto written = streamed(pipeline::FrameSource::semanticKitti(dir(6), config), config, 1, nullptr);
  ASSERT_EQ(one.size(), 15u);
  ASSERT_EQ(written.size(), 15u);
  size_t total = 0;
  for (size_t i = 0; i < one.size(); ++i) {
    expectSameNodes(one[i], two[i], i);
    expectSameNodes(one[i], written[i], i);
    total += one[i].size();
    // Random access (the pair-list protocol) reads the frame's scans itself and gives the same frame.
    if (i == 3 || i == 14) expectSameNodes(one[i], raw.load(i).nodes, i);
  }
  EXPECT_GT(total, 15u);
  // At most 6 raw scans of the 16 × 256 sensor, 16 bytes per point.
  EXPECT_GT(max_bytes, 0u);
  EXPECT_LE(max_bytes, 6u * 16 * 256 * 16);
}

TEST_F(AccumulatingSource, RefusesNodeFilesAndAWrongPoseCount) {
  const Config config;
  pipeline::FrameSource raw = pipeline::FrameSource::semanticKitti(dir(1), config);
  std::vector<Eigen::Isometry3d> poses(14, Eigen::Isometry3d::Identity());
  EXPECT_THAT([&] { raw.accumulate(6, poses); }, ThrowsMessage<Error>(HasSubstr("14 poses for 15 frames")));
  EXPECT_THAT([&] { raw.accumulate(0, poses); }, ThrowsMessage<Error>(HasSubstr("must be 1..1000")));
  EXPECT_EQ(raw.accumulated(), 1);
}

}  // namespace
}  // namespace sgtllc
