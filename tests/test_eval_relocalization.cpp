// The relocalization protocol's metrics (include/sgtllc/eval/relocalization.h) on hand-built poses whose every
// count and ratio is known in advance.
#include <gtest/gtest.h>

#include <cmath>

#include "sgtllc/eval/relocalization.h"
#include "sgtllc/types.h"

namespace sgtllc::eval {
namespace {

Eigen::Isometry3d pose(double x, double y, double yaw_deg = 0.0) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, 0.0);
  return T;
}

/// Map frames every 10 m along x, each turned a little so a frame mix-up shows in the pose.
std::vector<Eigen::Isometry3d> mapPoses() {
  std::vector<Eigen::Isometry3d> map;
  for (int i = 0; i <= 10; ++i) map.push_back(pose(10.0 * i, 0.0, 7.0 * i));
  return map;
}

/// The pose of a relocalization whose pose the test does not look at.
const Eigen::Isometry3d kNone = Eigen::Isometry3d::Identity();

RelocalizationQuery query(long number, int map_frame, bool accepted, const Eigen::Isometry3d& T) {
  RelocalizationQuery q;
  q.query_number = number;
  q.map_frame = map_frame;
  q.accepted = accepted;
  q.T_mapframe_query = T;
  return q;
}

/// T_mapframe_query from the ground truth, then moved by @p dx m along the map frame's x and turned by @p deg.
Eigen::Isometry3d estimate(const Eigen::Isometry3d& map, const Eigen::Isometry3d& q, double dx, double deg) {
  Eigen::Isometry3d T = map.inverse() * q;
  T.linear() = Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix() * T.linear();
  T.translation() += Eigen::Vector3d(dx, 0.0, 0.0);
  return T;
}

TEST(Relocalization, CountsAndRatiosOfAHandBuiltRun) {
  const std::vector<Eigen::Isometry3d> map = mapPoses();
  const std::vector<Eigen::Isometry3d> poses = {
      pose(1, 0, 3),    // 0: positive (1 m from map 0); correct, exact pose
      pose(21, 2, 40),  // 1: positive (2.24 m from map 2); correct, 0.5 m and 2° off: a pose success
      pose(40, 0),      // 2: positive; accepted with map 5, 10 m away: false
      pose(60, 0),      // 3: positive; not accepted
      pose(80, 1),      // 4: positive; correct frame, 3 m off: no pose success
      pose(50, 30),     // 5: negative (30 m from every map frame); accepted: a false relocalization
      pose(0, 50),      // 6: negative; not accepted
      pose(100, 10),    // 7: neither (10 m from map 10); accepted with map 10: between 3 and 20 m
  };
  const std::vector<RelocalizationQuery> queries = {
      query(0, 0, true, estimate(map[0], poses[0], 0.0, 0.0)),
      query(1, 2, true, estimate(map[2], poses[1], 0.5, 2.0)),
      query(2, 5, true, estimate(map[5], poses[2], 0.0, 0.0)),
      query(3, 6, false, kNone),
      query(4, 8, true, estimate(map[8], poses[4], 3.0, 0.0)),
      query(5, 5, true, kNone),
      query(6, -1, false, kNone),
      query(7, 10, true, estimate(map[10], poses[7], 0.0, 0.0)),
  };
  const RelocalizationMetrics m = relocalizationMetrics(queries, map, poses);
  EXPECT_EQ(m.queries, 8);
  EXPECT_EQ(m.positives, 5);
  EXPECT_EQ(m.negatives, 2);
  EXPECT_EQ(m.accepted, 6);
  EXPECT_EQ(m.accepted_near, 3);
  EXPECT_EQ(m.accepted_between, 2);
  EXPECT_EQ(m.accepted_far, 1);
  EXPECT_EQ(m.accepted_negatives, 1);
  EXPECT_EQ(m.pose_successes, 2);
  EXPECT_DOUBLE_EQ(*m.recall_at_1, 3.0 / 5.0);
  EXPECT_DOUBLE_EQ(*m.precision, 3.0 / 6.0);
  EXPECT_DOUBLE_EQ(*m.precision_no_between, 3.0 / 4.0);
  EXPECT_DOUBLE_EQ(*m.pose_success, 2.0 / 3.0);
  EXPECT_NEAR(*m.rte_mean_m, 0.25, 1e-12);
  EXPECT_NEAR(*m.rre_mean_deg, 1.0, 1e-9);
  EXPECT_DOUBLE_EQ(*m.false_rate, 0.5);
  // Judged by the pose in the world: 0, 1 and 7 are placed, and so is 2, whose pose is right although the frame it
  // names is 10 m away; 4 (3 m off) and 5 (30 m off) are not.
  EXPECT_EQ(m.accepted_placed, 4);
  EXPECT_EQ(m.positives_placed, 3);
  EXPECT_DOUBLE_EQ(*m.precision_pose, 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(*m.recall_at_1_pose, 3.0 / 5.0);
  const nlohmann::ordered_json j = relocalizationJson(m);
  EXPECT_DOUBLE_EQ(j.at("reloc_precision_pose").get<double>(), 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(j.at("reloc_recall_at_1_pose").get<double>(), 3.0 / 5.0);
  EXPECT_EQ(j.at("reloc_accepted_placed").get<int>(), 4);
}

TEST(Relocalization, ThresholdsAreInclusiveAtThreeAndExclusiveAtTwenty) {
  const std::vector<Eigen::Isometry3d> map = {pose(0, 0)};
  const std::vector<Eigen::Isometry3d> poses = {pose(3, 0), pose(20, 0), pose(20.001, 0)};
  const RelocalizationMetrics m =
      relocalizationMetrics({query(0, 0, true, estimate(map[0], poses[0], 0, 0)), query(1, 0, true, kNone),
                             query(2, 0, true, kNone)},
                            map, poses);
  EXPECT_EQ(m.positives, 1);
  EXPECT_EQ(m.negatives, 1);
  EXPECT_EQ(m.accepted_near, 1);
  EXPECT_EQ(m.accepted_between, 1);
  EXPECT_EQ(m.accepted_far, 1);
  EXPECT_DOUBLE_EQ(*m.recall_at_1, 1.0);
  EXPECT_DOUBLE_EQ(*m.false_rate, 1.0);
}

TEST(Relocalization, RatiosWithoutADenominatorAreNotAvailable) {
  const std::vector<Eigen::Isometry3d> map = {pose(0, 0)};
  RelocalizationMetrics m = relocalizationMetrics({}, map, {pose(0, 0)});
  EXPECT_EQ(m.queries, 0);
  EXPECT_FALSE(m.recall_at_1 || m.precision || m.precision_no_between || m.pose_success || m.rte_mean_m ||
               m.rre_mean_deg || m.false_rate || m.precision_pose || m.recall_at_1_pose);
  // One positive, nothing accepted: recall 0, the rest n/a.
  m = relocalizationMetrics({query(0, -1, false, kNone)}, map, {pose(1, 0)});
  ASSERT_TRUE(m.recall_at_1);
  EXPECT_EQ(*m.recall_at_1, 0.0);
  EXPECT_FALSE(m.precision || m.pose_success || m.false_rate || m.rte_mean_m);

  const nlohmann::ordered_json j = relocalizationJson(m);
  EXPECT_EQ(j.at("reloc_recall_at_1").get<double>(), 0.0);
  for (const char* key : {"reloc_precision", "reloc_pose_success", "reloc_false_rate", "reloc_rte_mean_m"}) {
    EXPECT_TRUE(j.at(key).is_null()) << key;
  }
  EXPECT_EQ(j.at("reloc_positives").get<int>(), 1);
  EXPECT_EQ(j.at("reloc_queries").get<int>(), 1);
}

TEST(Relocalization, BadQueriesAreRefusedByNumber) {
  const std::vector<Eigen::Isometry3d> map = {pose(0, 0)}, poses = {pose(0, 0), pose(1, 0)};
  auto message = [&](const std::vector<RelocalizationQuery>& q) {
    try {
      relocalizationMetrics(q, map, poses);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({query(2, 0, true, kNone)}),
            "relocalization query 2: no ground-truth pose (the query sequence has 2)");
  EXPECT_EQ(message({query(1, 0, true, kNone), query(1, 0, true, kNone)}), "relocalization query 1 appears twice");
  EXPECT_EQ(message({query(0, 1, true, kNone)}), "relocalization query 0: map frame 1 is not in the map (1 frames)");
  EXPECT_EQ(message({query(0, -1, true, kNone)}), "relocalization query 0 is accepted but names no map frame");
  RelocalizationProtocol bad;
  bad.negative_distance = 1.0;
  EXPECT_THROW(relocalizationMetrics({}, map, poses, bad), Error);
}

}  // namespace
}  // namespace sgtllc::eval
