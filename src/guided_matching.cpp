#include "sgtllc/guided_matching.h"

#include <limits>

#include "sgtllc/ransac.h"

namespace sgtllc {

std::vector<NodeMatch> pairsUnderPose(const SemanticGraph& query, const SemanticGraph& match,
                                      const Eigen::Matrix4d& T_match_query, double radius) {
  const Eigen::Matrix3d R = T_match_query.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = T_match_query.topRightCorner<3, 1>();
  const int m = query.size(), n = match.size();
  std::vector<Eigen::Vector3d> moved(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i) moved[i] = R * query.nodes[i].centre + t;
  // Nearest same-class node of each side under the pose; graphs hold tens of nodes, so a full scan is cheap.
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<int> query_nearest(static_cast<size_t>(m), -1), match_nearest(static_cast<size_t>(n), -1);
  std::vector<double> query_d2(static_cast<size_t>(m), kNone), match_d2(static_cast<size_t>(n), kNone);
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      if (query.nodes[i].label != match.nodes[j].label) continue;
      const double d2 = (moved[i] - match.nodes[j].centre).squaredNorm();
      if (d2 < query_d2[i]) {
        query_d2[i] = d2;
        query_nearest[i] = j;
      }
      if (d2 < match_d2[j]) {
        match_d2[j] = d2;
        match_nearest[j] = i;
      }
    }
  }
  std::vector<NodeMatch> pairs;
  const double r2 = radius * radius;
  for (int i = 0; i < m; ++i) {
    const int j = query_nearest[i];
    if (j >= 0 && match_nearest[j] == i && query_d2[i] < r2) pairs.push_back({i, j, 0.0});
  }
  return pairs;
}

GuidedMatch guidedMatching(const SemanticGraph& query, const SemanticGraph& match, const Eigen::Matrix4d& T_match_query,
                           double radius, size_t more_than, double max_tilt, int rounds) {
  GuidedMatch best;
  Eigen::Matrix4d T = T_match_query;
  for (int round = 0; round < rounds; ++round) {
    std::vector<NodeMatch> pairs = pairsUnderPose(query, match, T, radius);
    if (pairs.size() <= std::max(more_than, best.pairs.size())) break;
    std::vector<Eigen::Vector3d> source, target;
    for (const NodeMatch& p : pairs) {
      source.push_back(query.nodes[p.query].centre);
      target.push_back(match.nodes[p.match].centre);
    }
    T = fitRigid(source, target);
    if (!isUpright(T, max_tilt)) break;  // nearly collinear centres leave the turn about their line free
    best.pairs = std::move(pairs);
    best.T_match_query = T;
  }
  return best;
}

}  // namespace sgtllc
