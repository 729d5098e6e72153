// The segmentation-error model: ground truth at rate 0, network-like errors otherwise — in whole object parts and
// along boundaries rather than as independent flips — deterministic, and growing with the rate.
#include <gtest/gtest.h>

#include "sgtllc/config.h"
#include "sgtllc/node_extraction.h"
#include "sgtllc/sim/label_noise.h"
#include "sgtllc/sim/simulator.h"

namespace sgtllc::sim {
namespace {

class SimLabels : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SimConfig config;
    config.frames = 60;
    config.seed = 21;
    config.sensor.columns = 1024;
    sim_ = new Simulator(config);
    for (int i : {10, 30, 50}) {
      const FramePose& p = sim_->poses()[i];
      scans_.push_back(castScan(sim_->world(), sim_->sensor(), p.T_world_lidar, p.time, i, config.seed));
    }
  }
  static void TearDownTestSuite() {
    delete sim_;
    sim_ = nullptr;
    scans_.clear();
  }

  /// Share of points whose semantic label differs from the truth.
  static double errorRate(double rate) {
    size_t wrong = 0, total = 0;
    for (size_t s = 0; s < scans_.size(); ++s) {
      const std::vector<uint32_t> truth = trueLabels(scans_[s]);
      const std::vector<uint32_t> pred = predictLabels(scans_[s], rate, 21, static_cast<int64_t>(s));
      for (size_t i = 0; i < truth.size(); ++i) wrong += (truth[i] & 0xFFFF) != (pred[i] & 0xFFFF);
      total += truth.size();
    }
    return static_cast<double>(wrong) / total;
  }

  static Simulator* sim_;
  static std::vector<RawScan> scans_;
};

Simulator* SimLabels::sim_ = nullptr;
std::vector<RawScan> SimLabels::scans_;

TEST_F(SimLabels, RateZeroIsGroundTruth) {
  for (size_t s = 0; s < scans_.size(); ++s) EXPECT_EQ(predictLabels(scans_[s], 0.0, 21, 5), trueLabels(scans_[s]));
}

TEST_F(SimLabels, ErrorsGrowWithTheRateAndAreDeterministic) {
  const double low = errorRate(0.05), mid = errorRate(kDefaultLabelNoise), high = errorRate(0.4);
  EXPECT_GT(low, 0.0);
  EXPECT_LT(low, mid);
  EXPECT_LT(mid, high);
  EXPECT_LT(mid, 0.15);  // a good network gets most points right
  EXPECT_EQ(predictLabels(scans_[0], 0.1, 21, 3), predictLabels(scans_[0], 0.1, 21, 3));
  EXPECT_NE(predictLabels(scans_[0], 0.1, 21, 3), predictLabels(scans_[0], 0.1, 22, 3));
}

TEST_F(SimLabels, ErrorsAreSpatiallyCoherent) {
  // A wrong label usually has a range-image neighbour with the same wrong label (a wrong part or a bled
  // boundary); independent flips at the same rate would almost never have one.
  size_t wrong = 0, supported = 0;
  for (size_t s = 0; s < scans_.size(); ++s) {
    const RawScan& scan = scans_[s];
    const std::vector<uint32_t> truth = trueLabels(scan);
    const std::vector<uint32_t> pred = predictLabels(scan, kDefaultLabelNoise, 21, static_cast<int64_t>(s));
    std::vector<int32_t> point_of(static_cast<size_t>(scan.rows) * scan.columns, -1);
    for (size_t i = 0; i < scan.ray.size(); ++i) point_of[scan.ray[i]] = static_cast<int32_t>(i);
    for (size_t i = 0; i < pred.size(); ++i) {
      if ((pred[i] & 0xFFFF) == (truth[i] & 0xFFFF)) continue;
      ++wrong;
      for (int d : {-1, 1, -scan.rows, scan.rows}) {
        const int ray = scan.ray[i] + d;
        if (ray < 0 || ray >= static_cast<int>(point_of.size()) || point_of[ray] < 0) continue;
        const size_t q = static_cast<size_t>(point_of[ray]);
        if ((pred[q] & 0xFFFF) == (pred[i] & 0xFFFF) && (truth[q] & 0xFFFF) != (pred[q] & 0xFFFF)) {
          ++supported;
          break;
        }
      }
    }
  }
  ASSERT_GT(wrong, 500u);
  EXPECT_GT(static_cast<double>(supported) / wrong, 0.6);
}

TEST_F(SimLabels, NoiseChangesNodesModestly) {
  // Label errors should hurt the semantic graph, not destroy it: most nodes survive, few spurious ones appear.
  const Config config;
  const NodeExtractor extractor(config.cluster, config.labels);
  int truth_nodes = 0, noisy_nodes = 0;
  for (size_t s = 0; s < scans_.size(); ++s) {
    LabeledCloud cloud{scans_[s].points, trueLabels(scans_[s])};
    truth_nodes += static_cast<int>(extractor.extract(cloud).nodes.size());
    cloud.labels = predictLabels(scans_[s], kDefaultLabelNoise, 21, static_cast<int64_t>(s));
    noisy_nodes += static_cast<int>(extractor.extract(cloud).nodes.size());
  }
  ASSERT_GT(truth_nodes, 30);
  EXPECT_GT(noisy_nodes, 0.6 * truth_nodes);
  EXPECT_LT(noisy_nodes, 1.3 * truth_nodes);
}

TEST_F(SimLabels, NetworkLabelSpaceAndInstances) {
  for (size_t s = 0; s < scans_.size(); ++s) {
    const std::vector<uint32_t> truth = trueLabels(scans_[s]);
    const std::vector<uint32_t> pred = predictLabels(scans_[s], 0.3, 21, static_cast<int64_t>(s));
    for (size_t i = 0; i < pred.size(); ++i) {
      const uint32_t id = pred[i] & 0xFFFF, instance = pred[i] >> 16;
      EXPECT_LT(id, 252u) << "moving classes are not in a network's output";
      if (instance != 0) {
        EXPECT_EQ(instance, truth[i] >> 16);
        EXPECT_TRUE(id >= 10 && id <= 32) << id;
      }
    }
  }
}

}  // namespace
}  // namespace sgtllc::sim
