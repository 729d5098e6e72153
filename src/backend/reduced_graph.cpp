#include "reduced_graph.h"

#include <algorithm>

#include "ceres_pose_graph.h"
#include "se3.h"

namespace sgtllc::backend::internal {

int ReducedGraph::index(int frame) const {
  return static_cast<int>(std::lower_bound(anchors.begin(), anchors.end(), frame) - anchors.begin());
}

ReducedGraph reduceOdometry(const std::vector<Edge>& odometry, const std::vector<Matrix6d>& covariance,
                            std::vector<int> anchors) {
  const int n = static_cast<int>(odometry.size()) + 1;
  anchors.push_back(0);
  anchors.push_back(n - 1);
  std::sort(anchors.begin(), anchors.end());
  anchors.erase(std::unique(anchors.begin(), anchors.end()), anchors.end());

  ReducedGraph r;
  r.anchors = std::move(anchors);
  r.T_anchor_frame.resize(n, Eigen::Isometry3d::Identity());
  r.covariance_anchor_frame.resize(n, Matrix6d::Zero());
  for (size_t k = 0; k + 1 < r.anchors.size(); ++k) {
    const int a = r.anchors[k], b = r.anchors[k + 1];
    for (int i = a + 1; i <= b; ++i) {
      const Edge& step = odometry[i - 1];
      const Matrix6d A = adjointInverse(step.T_from_to);
      r.T_anchor_frame[i] = r.T_anchor_frame[i - 1] * step.T_from_to;
      r.covariance_anchor_frame[i] = A * r.covariance_anchor_frame[i - 1] * A.transpose() + covariance[i - 1];
    }
    Edge chain;
    chain.from = static_cast<int>(k);
    chain.to = static_cast<int>(k + 1);
    chain.T_from_to = r.T_anchor_frame[b];
    const Matrix6d sigma = 0.5 * (r.covariance_anchor_frame[b] + r.covariance_anchor_frame[b].transpose());
    chain.information = sigma.inverse();
    chain.information = 0.5 * (chain.information + chain.information.transpose()).eval();
    chain.kind = EdgeKind::kOdometry;
    r.chains.push_back(chain);
    // The chain's end is the next chain's start.
    r.T_anchor_frame[b] = Eigen::Isometry3d::Identity();
    r.covariance_anchor_frame[b] = Matrix6d::Zero();
  }
  return r;
}

void redistribute(const ReducedGraph& reduced, std::vector<Eigen::Isometry3d>& poses) {
  for (size_t k = 0; k + 1 < reduced.anchors.size(); ++k) {
    const int a = reduced.anchors[k], b = reduced.anchors[k + 1];
    if (b == a + 1) continue;
    const Edge& chain = reduced.chains[k];
    const Vector6d g = chain.information * edgeError(chain, poses[a], poses[b]);
    const Eigen::Isometry3d T_world_a = poses[a];
    for (int i = a + 1; i < b; ++i) {
      const Eigen::Isometry3d& T_a_i = reduced.T_anchor_frame[i];
      // Ad(Z_i_b)⁻ᵀ g = (R u, [t]× R u + R w) for Z_i_b = (R, t), g = (u, w).
      const Eigen::Isometry3d T_i_b = T_a_i.inverse() * chain.T_from_to;
      const Eigen::Vector3d Ru = T_i_b.rotation() * g.head<3>();
      Vector6d h;
      h << Ru, T_i_b.translation().cross(Ru) + T_i_b.rotation() * g.tail<3>();
      poses[i] = retract(T_world_a * T_a_i, reduced.covariance_anchor_frame[i] * h);
    }
  }
}

}  // namespace sgtllc::backend::internal
