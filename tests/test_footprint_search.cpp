// The footprint search (algorithm §7.9, footprint_search.h): the shift of a pose under which two footprints agree
// best, on a synthetic street whose answer is known, against footprintOverlap as the brute-force reference.
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "sgtllc/footprint.h"
#include "sgtllc/footprint_search.h"

namespace sgtllc {
namespace {

constexpr uint32_t kBuildingId = 50, kPoleId = 80;  // SemanticKITTI raw ids (LabelConfig's default preset)

/// A straight street along y, as a sensor at (0, @p ahead) sees it: a wall at x = −6 from y = −60 to 60, and
/// kiosks (1.5 m square) at x = 5 at uneven spacing, so that only one shift along the street puts every kiosk on a
/// kiosk.
Footprint street(double ahead) {
  LabeledCloud c;
  const auto add = [&](double x, double y, uint32_t id) {
    c.points.emplace_back(static_cast<float>(x), static_cast<float>(y - ahead), 0.5f);
    c.labels.push_back(id);
  };
  for (double y = -60.0; y <= 60.0; y += 0.1) add(-5.95, y, kBuildingId);
  for (double y0 : {-21.3, -10.8, -3.1, 6.2, 14.4, 25.7}) {
    for (double x = 5.05; x < 6.5; x += 0.1) {
      for (double y = y0; y < y0 + 1.5; y += 0.1) add(x, y, kPoleId);
    }
  }
  return computeFootprint(c, LabelMap{LabelConfig{}}, VerificationConfig{});
}

Eigen::Matrix4d translation(double x, double y) {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T(0, 3) = x;
  T(1, 3) = y;
  return T;
}

TEST(FootprintSearch, FindsTheShiftAlongAStreetThatTheNodesMissed) {
  // The query's sensor is 4 m ahead of the match's; the nodes (a wall centred on the part each scan sees) said it
  // had not moved. Under the identity the wall agrees and the kiosks do not; 4 m ahead, everything does.
  const Footprint match = street(0.0), query = street(4.0);
  const FootprintShift s = bestFootprintShift(query, match, Eigen::Matrix4d::Identity(), 10.0, 20);
  ASSERT_GT(s.compared, 0);
  EXPECT_DOUBLE_EQ(s.shift.x(), 0.0);
  EXPECT_DOUBLE_EQ(s.shift.y(), 4.0);
  EXPECT_DOUBLE_EQ(s.share, 1.0);
  EXPECT_LT(s.unshifted_share, 0.8);
  // Every cell stays well inside the match's grid, so the shares are footprintOverlap's under both poses.
  EXPECT_DOUBLE_EQ(s.unshifted_share, footprintOverlap(query, match, Eigen::Matrix4d::Identity()).share);
  EXPECT_DOUBLE_EQ(s.share, footprintOverlap(query, match, translation(0.0, 4.0)).share);
  EXPECT_EQ(s.compared, footprintOverlap(query, match, Eigen::Matrix4d::Identity()).compared);
}

TEST(FootprintSearch, AnOddNumberOfCellsIsFoundByTheFinePass) {
  // 3.5 m is 7 cells: the coarse pass, every second cell, lands next to it and the fine pass on it.
  const Footprint match = street(0.0), query = street(-3.5);
  const FootprintShift s = bestFootprintShift(query, match, Eigen::Matrix4d::Identity(), 10.0, 20);
  EXPECT_DOUBLE_EQ(s.shift.x(), 0.0);
  EXPECT_DOUBLE_EQ(s.shift.y(), -3.5);
  EXPECT_DOUBLE_EQ(s.share, 1.0);
}

TEST(FootprintSearch, ARightPoseStaysWhereItsNeighboursTie) {
  // The pose is right: no shift agrees better. Those one cell off agree as well (the cell of slack), and the zero
  // shift, in the middle of that plateau, has the best neighbours.
  const Footprint match = street(0.0), query = street(2.0);
  const FootprintShift s = bestFootprintShift(query, match, translation(0.0, 2.0), 10.0, 20);
  EXPECT_DOUBLE_EQ(s.shift.norm(), 0.0);
  EXPECT_DOUBLE_EQ(s.share, 1.0);
  EXPECT_DOUBLE_EQ(s.unshifted_share, 1.0);
}

TEST(FootprintSearch, TheReachBoundsTheShift) {
  // 4 m ahead, searched within 2 m: the best it can do is 2 m, where the wall agrees and the kiosks do not quite.
  const Footprint match = street(0.0), query = street(4.0);
  const FootprintShift s = bestFootprintShift(query, match, Eigen::Matrix4d::Identity(), 2.0, 20);
  EXPECT_LE(std::abs(s.shift.x()), 2.0);
  EXPECT_LE(std::abs(s.shift.y()), 2.0);
  EXPECT_LT(s.share, 1.0);
}

TEST(FootprintSearch, NothingToCompareIsNoSearch) {
  const Footprint match = street(0.0), query = street(4.0);
  EXPECT_EQ(bestFootprintShift(Footprint{}, match, Eigen::Matrix4d::Identity(), 10.0, 20).compared, 0);
  EXPECT_EQ(bestFootprintShift(query, Footprint{}, Eigen::Matrix4d::Identity(), 10.0, 20).compared, 0);
  // A pose that puts the query's cells out of the match's reach compares none.
  const FootprintShift far = bestFootprintShift(query, match, translation(500.0, 0.0), 10.0, 20);
  EXPECT_EQ(far.compared, 0);
  EXPECT_DOUBLE_EQ(far.shift.norm(), 0.0);
  // Fewer occupied cells than asked for.
  EXPECT_EQ(bestFootprintShift(query, match, Eigen::Matrix4d::Identity(), 10.0, 100000).compared, 0);
  Eigen::Matrix4d nan = Eigen::Matrix4d::Identity();
  nan(0, 3) = NAN;
  EXPECT_EQ(bestFootprintShift(query, match, nan, 10.0, 20).compared, 0);
  // A dilated query (only stored frames are) is refused, as footprintOverlap refuses it.
  EXPECT_EQ(bestFootprintShift(dilateFootprint(query), match, Eigen::Matrix4d::Identity(), 10.0, 20).compared, 0);
}

}  // namespace
}  // namespace sgtllc
