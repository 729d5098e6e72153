// The class-pair distance histogram key (retrieval/distance_histogram.h): hand-computed votes, invariances, its
// robustness to one vanishing node against the max-pooled Des^G (G2), and the detector storing it.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "sgtllc/database.h"
#include "sgtllc/detector.h"
#include "sgtllc/global_descriptor.h"
#include "sgtllc/retrieval/distance_histogram.h"
#include "sgtllc/retrieval/retrieval_key.h"

namespace {

using namespace sgtllc;
using retrieval::classPairIndex;
using retrieval::computeDistanceHistogram;
using retrieval::distanceHistogramSize;
using retrieval::numClassPairs;

std::vector<float> histogram(const std::vector<Node>& nodes, const RetrievalConfig& rc = {}) {
  return computeDistanceHistogram(buildGraph(nodes, GraphConfig{}), rc);
}

double distance2(const std::vector<float>& a, const std::vector<float>& b) {
  double d2 = 0.0;
  for (size_t i = 0; i < a.size(); ++i) d2 += (static_cast<double>(a[i]) - b[i]) * (static_cast<double>(a[i]) - b[i]);
  return d2;
}

TEST(ClassPairIndex, EnumeratesUnorderedPairsOnce) {
  for (int c : {1, 7, 8, kMaxClasses}) {
    std::set<int> seen;
    for (int a = 0; a < c; ++a) {
      for (int b = a; b < c; ++b) {
        EXPECT_EQ(classPairIndex(a, b, c), classPairIndex(b, a, c));
        seen.insert(classPairIndex(a, b, c));
      }
    }
    ASSERT_EQ(static_cast<int>(seen.size()), numClassPairs(c));
    EXPECT_EQ(*seen.begin(), 0);
    EXPECT_EQ(*seen.rbegin(), numClassPairs(c) - 1);
  }
  EXPECT_EQ(numClassPairs(7), 28);
  EXPECT_EQ(classPairIndex(kBuilding, kPole, 7), 5);
  EXPECT_EQ(classPairIndex(kFence, kFence, 7), 7);
  EXPECT_EQ(distanceHistogramSize(7, 10), 280);
  EXPECT_EQ(distanceHistogramSize(8, 10), 360);
}

TEST(DistanceHistogram, HandComputedVotes) {
  // Bins 2 m wide (20 m / 10, as the defaults' 60 m / 30), centred at 1, 3, 5, … m. Building–building 3 m: on the centre of bin 1.
  // Building–pole 4 m: half way between bins 1 and 2. Building–pole 5 m: on the centre of bin 2. Pole–trunk
  // 0.5 m: below the first centre, all in bin 0. Building–trunk 4.5 m and √29.25 m: split by hand below.
  const std::vector<Node> far = {{{0, 0, 0}, kBuilding}, {{3, 0, 0}, kBuilding}, {{0, 4, 0}, kPole},
                                 {{0, 4.5, 0}, kTrunk}};
  RetrievalConfig rc;
  rc.histogram_range = 20.0;
  rc.histogram_bins = 10;
  const std::vector<float> key = histogram(far, rc);
  ASSERT_EQ(key.size(), 280u);
  // Raw votes (before the L2 scaling), cell = 10 · pair + bin.
  std::vector<double> votes(280, 0.0);
  votes[10 * classPairIndex(kBuilding, kBuilding, 7) + 1] += 1.0;   // 3 m
  votes[10 * classPairIndex(kBuilding, kPole, 7) + 1] += 0.5;       // 4 m
  votes[10 * classPairIndex(kBuilding, kPole, 7) + 2] += 0.5;
  votes[10 * classPairIndex(kBuilding, kPole, 7) + 2] += 1.0;       // 5 m
  votes[10 * classPairIndex(kPole, kTrunk, 7) + 0] += 1.0;          // 0.5 m
  const double d13 = std::sqrt(0.0 + 4.5 * 4.5), d23 = std::sqrt(9.0 + 4.5 * 4.5);  // building–trunk
  for (double d : {d13, d23}) {
    const double x = d / 2.0 - 0.5;
    const int b = static_cast<int>(x);
    votes[10 * classPairIndex(kBuilding, kTrunk, 7) + b] += 1.0 - (x - b);
    votes[10 * classPairIndex(kBuilding, kTrunk, 7) + b + 1] += x - b;
  }
  double norm2 = 0.0;
  for (double v : votes) norm2 += v * v;
  for (int i = 0; i < 280; ++i) EXPECT_NEAR(key[i], votes[i] / std::sqrt(norm2), 1e-6) << "cell " << i;

  // Pairs at or beyond the range do not vote: at 3 m (bins 0.3 m wide) only the 0.5 m pole–trunk pair is left
  // (the 3 m pair is not < 3 m), at x = 0.5 / 0.3 − 0.5 = 7/6 bins: 5/6 to bin 1, 1/6 to bin 2, then unit norm.
  rc.histogram_range = 3.0;
  const std::vector<float> near = histogram(far, rc);
  const int pole_trunk = 10 * classPairIndex(kPole, kTrunk, 7);
  for (int i = 0; i < 280; ++i) {
    const double expected = i == pole_trunk + 1   ? 5.0 / std::sqrt(26.0)
                            : i == pole_trunk + 2 ? 1.0 / std::sqrt(26.0)
                                                  : 0.0;
    EXPECT_NEAR(near[i], expected, 1e-6) << "cell " << i;
  }
  // No pair in range: the zero vector, not NaN.
  rc.histogram_range = 0.1;
  for (float v : histogram(far, rc)) EXPECT_EQ(v, 0.0f);
}

/// @p n nodes of random classes, uniform in a square of side @p side (m), fixed seed.
std::vector<Node> randomScene(uint32_t seed, int n, double side) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, side);
  std::uniform_int_distribution<int> label(0, kNumPaperClasses - 1);
  std::vector<Node> nodes;
  for (int i = 0; i < n; ++i) nodes.push_back({{u(rng), u(rng), 0.2 * u(rng)}, label(rng)});
  return nodes;
}

TEST(DistanceHistogram, InvariantToRigidMotionAndNodeOrder) {
  const std::vector<Node> nodes = randomScene(3, 30, 40.0);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(2.1, Eigen::Vector3d(0.1, 0.2, 1.0).normalized()).toRotationMatrix();
  std::vector<Node> moved = nodes;
  for (Node& n : moved) n.centre = R * n.centre + Eigen::Vector3d(-12.0, 7.5, 0.3);
  std::reverse(moved.begin(), moved.end());
  const std::vector<float> a = histogram(nodes), b = histogram(moved);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-6);
  EXPECT_NEAR(distance2(a, std::vector<float>(a.size(), 0.0f)), 1.0, 1e-6);  // unit norm
}

TEST(DistanceHistogram, OneVanishingNodeKeepsTheNearestFrameWhereG2LosesIt) {
  // Stored: frame A (20 nodes within 12 m) and frame B = A without its node 0, scaled by 1.5 (every pair stays
  // within σ_d, so the graph and its longest paths scale with it). Des^G (G2) is built from angles, so B has the
  // G2 of "A without node 0" exactly; the histogram keeps metric distances. The query is A with node 0 gone.
  const std::vector<Node> a = randomScene(11, 20, 12.0);
  const std::vector<Node> query(a.begin() + 1, a.end());
  const std::vector<Node> b = [&] {
    std::vector<Node> scaled = query;
    for (Node& n : scaled) n.centre *= 1.5;
    return scaled;
  }();

  Config g2, hist;  // hist: the default key, the histogram
  g2.retrieval.key = RetrievalKey::kGlobalDescriptor;
  for (const Config* config : {&g2, &hist}) {
    FrameDatabase db;
    for (const std::vector<Node>* f : {&a, &b}) {
      db.add({*f, retrieval::computeRetrievalKey(buildGraph(*f, config->graph), *config)});
    }
    const auto keyOf = [&](const std::vector<Node>& nodes) {
      return retrieval::computeRetrievalKey(buildGraph(nodes, config->graph), *config);
    };
    // The full frame finds itself under both keys.
    EXPECT_EQ(db.query(keyOf(a), 1, 1).at(0).frame, 0);
    const std::vector<RetrievedFrame> hits = db.query(keyOf(query), 1, 2);
    ASSERT_EQ(hits.size(), 2u);
    if (config == &g2) {
      EXPECT_EQ(hits[0].frame, 1) << "G2: the node that vanished held maxima, the scaled copy matches better";
      EXPECT_LT(hits[0].distance2, 1e-8);
    } else {
      EXPECT_EQ(hits[0].frame, 0) << "histogram: 19 of 190 votes went, the frame stays nearest";
      EXPECT_LT(hits[0].distance2, 0.1f);   // cos > 0.95
      EXPECT_GT(hits[1].distance2, 0.5f);   // the scaled copy is far
    }
  }
}

TEST(RetrievalKey, DetectorStoresTheConfiguredKey) {
  const std::vector<Node> nodes = randomScene(5, 25, 30.0);
  Config config;
  LoopDetector hist(config);
  hist.process(nodes);
  EXPECT_EQ(hist.database().globalDimension(), 28 * 30);  // 28 class pairs × 30 bins
  const std::vector<float> expected = computeDistanceHistogram(buildGraph(nodes, config.graph), config.retrieval);
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), hist.database().global(0)));
  EXPECT_EQ(retrieval::retrievalKeySize(config), 840);

  config.retrieval.key = RetrievalKey::kGlobalDescriptor;
  LoopDetector g2(config);
  g2.process(nodes);
  EXPECT_EQ(g2.database().globalDimension(), 343);
  const std::vector<float> des = computeGlobalDescriptor(buildGraph(nodes, config.graph), config.descriptor);
  EXPECT_TRUE(std::equal(des.begin(), des.end(), g2.database().global(0)));

  // Eight classes (the KITTI 00 object frames): 36 class pairs.
  Config eight;
  eight.addClass({"vehicle", {10}});
  std::vector<Node> with_vehicle = nodes;
  with_vehicle[0].label = 7;
  LoopDetector objects(eight);
  objects.process(with_vehicle);
  EXPECT_EQ(objects.database().globalDimension(), 36 * 30);
  EXPECT_EQ(retrieval::retrievalKeySize(eight), 1080);
}

}  // namespace
