// The relocalizer's own shortlist and the stream tracker (include/sgtllc/map/relocalization_tracker.h) on hand-built
// answers whose every decision is known in advance, and on the synthetic two-session world of test_map_support.h.
#include <gtest/gtest.h>

#include <algorithm>

#include "sgtllc/map/map.h"
#include "sgtllc/map/relocalization_tracker.h"
#include "sgtllc/map/relocalizer.h"
#include "sgtllc/types.h"
#include "test_map_support.h"

namespace sgtllc {
namespace {

Config trackerTestConfig() {
  Config config;
  config.retrieval.exclude_recent = 20;
  return config;
}

map::Map circleMap(bool poses = true) {
  const test::NodeSequence s = test::circleSequence(100);
  const Config config = trackerTestConfig();
  const LoopDetector detector = test::runNodes(s, config);
  return map::makeMap(detector.database(), config, s.names, poses ? s.poses : std::vector<Eigen::Matrix4d>{});
}

/// The hand-built answers below carry no inlier nodes, so the rotation check is off for them (it has its own test,
/// Relocalizer.RefusesAnAnswerWhoseInliersLieNearlyOnALine).
map::RelocalizerOptions handBuilt() {
  map::RelocalizerOptions options;
  options.max_rotation_uncertainty_deg = 0.0;
  return options;
}

/// A verified candidate: map frame @p frame, score @p score, the query @p dx m ahead of the frame (its x axis).
Candidate candidate(int frame, double score, double dx = 0.0, Rejection rejection = Rejection::kNone) {
  Candidate c;
  c.frame = frame;
  c.match.rejection = rejection;
  c.match.score = score;
  c.match.T_match_query = Eigen::Matrix4d::Identity();
  c.match.T_match_query(0, 3) = dx;
  return c;
}

/// The relocalizer's answer for a search with these candidates (best = the highest score, a loop above σ_4 0.3).
map::Relocalization answer(const map::Relocalizer& r, std::vector<Candidate> candidates) {
  FrameResult search;
  search.candidates = std::move(candidates);
  search.best = -1;
  for (size_t c = 0; c < search.candidates.size(); ++c) {
    const MatchResult& m = search.candidates[c].match;
    if (m.rejection != Rejection::kNone) continue;
    if (search.best < 0 || m.score > search.candidates[static_cast<size_t>(search.best)].match.score) {
      search.best = static_cast<int>(c);
    }
  }
  search.is_loop = search.best >= 0 && search.candidates[static_cast<size_t>(search.best)].match.score > 0.3;
  const int best = search.best;
  return r.answerWith(std::move(search), best);
}

TEST(RelocalizationTracker, AcceptsAWeakerAnswerOnlyWhereTheTrackIs) {
  // Map frames lie 3.77 m apart on a circle of radius 60 m (100 per lap).
  const map::Relocalizer relocalizer(circleMap(), trackerTestConfig(), "m", handBuilt());
  map::RelocalizationTracker tracker(relocalizer);  // weak 0.2, gate 3 m + 2 m per frame, window 10

  // Before any accepted answer there is no track: a weak answer stays unaccepted.
  map::Relocalization r = tracker.track(answer(relocalizer, {candidate(10, 0.25)}));
  EXPECT_FALSE(r.localized);
  EXPECT_FALSE(r.tracked);
  // A strong answer starts the track at map frame 10.
  r = tracker.track(answer(relocalizer, {candidate(10, 0.5)}));
  EXPECT_TRUE(r.localized);
  EXPECT_FALSE(r.tracked);
  EXPECT_EQ(r.map_frame, 10);
  // One frame on: frame 11 is 3.77 m away, within 3 + 2 m. The far candidate scores higher but disagrees.
  r = tracker.track(answer(relocalizer, {candidate(11, 0.22), candidate(60, 0.29)}));
  EXPECT_TRUE(r.localized);
  EXPECT_TRUE(r.tracked);
  EXPECT_EQ(r.map_frame, 11);
  EXPECT_EQ(r.search.best, 0);
  EXPECT_DOUBLE_EQ(r.score, 0.22);
  // At or below weak_sigma, rejected, or too far from the track: not accepted (the track is held at frame 11).
  EXPECT_FALSE(tracker.track(answer(relocalizer, {candidate(12, 0.2)})).localized);
  EXPECT_FALSE(tracker.track(answer(relocalizer, {candidate(12, 0.28, 0.0, Rejection::kRansacFailed)})).localized);
  // Two frames since frame 11: reach 3 + 2·3 = 9 m; frame 14 is 11.3 m away, frame 13 7.5 m.
  EXPECT_FALSE(tracker.track(answer(relocalizer, {candidate(14, 0.28)})).localized);
  r = tracker.track(answer(relocalizer, {candidate(14, 0.28, -4.0), candidate(13, 0.21)}));
  EXPECT_TRUE(r.tracked);
  // Its pose places the query 4 m behind frame 14, which the nearest-frame answer turns into frame 13.
  EXPECT_EQ(r.map_frame, 13);
  EXPECT_DOUBLE_EQ(r.score, 0.28);
}

TEST(RelocalizationTracker, LosesTheTrackAfterTheWindow) {
  const map::Relocalizer relocalizer(circleMap(), trackerTestConfig(), "m", handBuilt());
  map::TrackingOptions options;
  options.window = 3;
  options.max_speed_m_per_frame = 10.0;
  map::RelocalizationTracker tracker(relocalizer, options);
  ASSERT_TRUE(tracker.track(answer(relocalizer, {candidate(20, 0.6)})).localized);
  for (int k = 0; k < 2; ++k) EXPECT_FALSE(tracker.track(answer(relocalizer, {})).localized);
  // The third frame since: still within the window.
  EXPECT_TRUE(tracker.track(answer(relocalizer, {candidate(22, 0.25)})).tracked);
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(tracker.track(answer(relocalizer, {})).localized);
  // The fourth frame since frame 22: the track is lost.
  EXPECT_FALSE(tracker.track(answer(relocalizer, {candidate(22, 0.25)})).localized);
  // reset() forgets it too.
  ASSERT_TRUE(tracker.track(answer(relocalizer, {candidate(30, 0.6)})).localized);
  tracker.reset();
  EXPECT_FALSE(tracker.track(answer(relocalizer, {candidate(30, 0.25)})).localized);
}

TEST(RelocalizationTracker, TracksNothingWithoutMapPosesAndRefusesBadOptions) {
  const map::Relocalizer relocalizer(circleMap(/*poses=*/false), trackerTestConfig(), "m", handBuilt());
  map::RelocalizationTracker tracker(relocalizer);
  EXPECT_TRUE(tracker.track(answer(relocalizer, {candidate(10, 0.5)})).localized);
  EXPECT_FALSE(tracker.track(answer(relocalizer, {candidate(10, 0.25)})).localized);
  map::TrackingOptions bad;
  bad.gate_m = 0.0;
  try {
    map::RelocalizationTracker(relocalizer, bad);
    FAIL() << "a zero gate was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("gate_m"), std::string::npos) << e.what();
  }
}

TEST(Relocalizer, VerifiesItsOwnShortlist) {
  const test::NodeSequence second = test::circleSequence(3, 3.0, 0.9, /*seed=*/99);
  Config config = trackerTestConfig();
  config.retrieval.num_candidates = 15;
  const map::Relocalizer wide(circleMap(), config);  // default: 50
  const map::Relocalizer own(circleMap(), config, "m", map::RelocalizerOptions{0});
  const map::Relocalizer narrow(circleMap(), config, "m", map::RelocalizerOptions{4});
  // Counted: the retrieved candidates; the top-1's map neighbours that the neighbour check adds are not.
  auto retrieved = [&](const map::Relocalizer& r) {
    const auto& candidates = r.localize(second.frames[0]).search.candidates;
    return std::count_if(candidates.begin(), candidates.end(), [](const Candidate& c) { return c.retrieved; });
  };
  EXPECT_EQ(retrieved(wide), 50);
  EXPECT_EQ(retrieved(own), 15);
  EXPECT_EQ(retrieved(narrow), 4);
  EXPECT_THROW(map::Relocalizer(circleMap(), config, "m", map::RelocalizerOptions{1001}), Error);
}

/// Eight nodes along x (−7 … 7 m) at y = ±@p a, signs chosen so that Σx·y = 0: the centred centres' singular
/// values are exactly √Σx² = 12.96 m and a·√8.
std::vector<Node> strip(double a) {
  const double x[] = {-7, -5, -3, -1, 1, 3, 5, 7};
  const double sign[] = {1, -1, -1, 1, 1, -1, -1, 1};
  std::vector<Node> nodes;
  for (int k = 0; k < 8; ++k) nodes.push_back(Node{Eigen::Vector3d(x[k], a * sign[k], 0.0), k % 3});
  return nodes;
}

/// Map frame @p frame verified with every node an inlier (node k of the query to node k of the frame).
Candidate allInliers(int frame, int nodes, double score) {
  Candidate c = candidate(frame, score);
  for (int k = 0; k < nodes; ++k) {
    c.match.associations.push_back(NodeMatch{k, k, 1.0});
    c.match.inliers.push_back(k);
  }
  return c;
}

TEST(Relocalizer, RefusesAnAnswerWhoseInliersLieNearlyOnALine) {
  // The bound is s₂ ≥ inlier_threshold / tan 5° = 0.4 / 0.08749 = 4.572 m: a = 1.5 gives s₂ = 4.243 m, a = 1.7
  // 4.808 m.
  test::NodeSequence s;
  for (double a : {1.5, 1.7}) {
    s.frames.push_back(strip(a));
    s.poses.push_back(Eigen::Matrix4d::Identity());
    s.names.push_back(std::to_string(s.names.size()));
  }
  const Config config = trackerTestConfig();
  const LoopDetector detector = test::runNodes(s, config);
  const map::Relocalizer relocalizer(map::makeMap(detector.database(), config, s.names, s.poses), config);
  ASSERT_EQ(relocalizer.map().database.nodes(0).size(), 8u);
  EXPECT_FALSE(relocalizer.rotationSupported(allInliers(0, 8, 0.9)));
  EXPECT_TRUE(relocalizer.rotationSupported(allInliers(1, 8, 0.9)));
  EXPECT_FALSE(relocalizer.rotationSupported(allInliers(1, 2, 0.9)));  // two inliers fix no rotation

  const map::Relocalization thin = answer(relocalizer, {allInliers(0, 8, 0.9)});
  EXPECT_TRUE(thin.search.is_loop);
  EXPECT_FALSE(thin.localized);
  EXPECT_TRUE(thin.weak_rotation);
  const map::Relocalization wide = answer(relocalizer, {allInliers(1, 8, 0.9)});
  EXPECT_TRUE(wide.localized);
  EXPECT_FALSE(wide.weak_rotation);
  // The check off: the thin strip is accepted; a bound out of range is refused.
  map::RelocalizerOptions off;
  off.max_rotation_uncertainty_deg = 0.0;
  const map::Relocalizer unchecked(map::makeMap(detector.database(), config, s.names, s.poses), config, "m", off);
  EXPECT_TRUE(answer(unchecked, {allInliers(0, 8, 0.9)}).localized);
  map::RelocalizerOptions bad;
  bad.max_rotation_uncertainty_deg = 90.0;
  EXPECT_THROW(map::Relocalizer(map::makeMap(detector.database(), config, s.names, s.poses), config, "m", bad),
               Error);
}

TEST(RelocalizationTracker, AStreamOfTheSecondSessionAgreesWithItsTruth) {
  const map::Relocalizer relocalizer(circleMap(), trackerTestConfig());
  const test::NodeSequence second = test::circleSequence(30, 3.0, 0.9, /*seed=*/99);
  map::RelocalizationTracker tracker(relocalizer);
  int localized = 0;
  for (size_t q = 0; q < second.frames.size(); ++q) {
    const map::Relocalization r = tracker.localize(second.frames[q]);
    const map::Relocalization alone = relocalizer.localize(second.frames[q]);
    // A frame accepted alone is answered the same in the stream.
    if (alone.localized) {
      EXPECT_FALSE(r.tracked);
      EXPECT_EQ(r.map_frame, alone.map_frame);
    }
    if (!r.localized) continue;
    ++localized;
    const Eigen::Vector3d error = r.T_world_query->topRightCorner<3, 1>() - second.poses[q].topRightCorner<3, 1>();
    EXPECT_LT(error.norm(), 0.3) << "query " << q;
  }
  EXPECT_GE(localized, 27);
}

}  // namespace
}  // namespace sgtllc
