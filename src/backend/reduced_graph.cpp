#include "reduced_graph.h"

#include <algorithm>
#include <utility>

#include <Eigen/LU>

#include "ceres_pose_graph.h"
#include "se3.h"

namespace sgtllc::backend::internal {

int ReducedGraph::indexAtOrBefore(int frame) const {
  return static_cast<int>(std::upper_bound(anchors.begin(), anchors.end(), frame) - anchors.begin()) - 1;
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
    r.chain_covariance.push_back(sigma);
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

namespace {

// The odometry from an anchor to a frame: the anchor's reduced index, T_anchor_frame and its covariance over the
// right perturbation at the frame.
struct Piece {
  int index = 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  Matrix6d covariance = Matrix6d::Zero();
};

// The pieces that reach @p frame from the anchor at or before it and back from the anchor after it (both the anchor
// itself when the frame is one).
std::pair<Piece, Piece> pieces(const ReducedGraph& reduced, int frame) {
  Piece before;
  before.index = reduced.indexAtOrBefore(frame);
  before.T = reduced.T_anchor_frame[frame];
  before.covariance = reduced.covariance_anchor_frame[frame];
  if (reduced.anchors[before.index] == frame) return {before, before};
  // Chain B → C through the frame x: Σ_B_C = Ad(T̂_x_C)⁻¹ Σ_B_x Ad(T̂_x_C)⁻ᵀ + Σ_x_C, so the piece x → C is what
  // the chain adds after x; inverted, C → x has covariance Ad(T̂_x_C) Σ_x_C Ad(T̂_x_C)ᵀ at x.
  const Edge& chain = reduced.chains[before.index];
  const Eigen::Isometry3d T_x_C = before.T.inverse() * chain.T_from_to;
  const Matrix6d A = adjointInverse(T_x_C);
  const Matrix6d sigma_x_C = reduced.chain_covariance[before.index] - A * before.covariance * A.transpose();
  const Matrix6d Ad = adjointInverse(T_x_C.inverse());
  Piece after;
  after.index = before.index + 1;
  after.T = T_x_C.inverse();
  after.covariance = Ad * sigma_x_C * Ad.transpose();
  after.covariance = 0.5 * (after.covariance + after.covariance.transpose()).eval();
  return {before, after};
}

// The shorter piece, by the translation variance it carries.
const Piece& shorter(const std::pair<Piece, Piece>& p) {
  const double before = p.first.covariance.topLeftCorner<3, 3>().trace();
  return p.second.covariance.topLeftCorner<3, 3>().trace() < before ? p.second : p.first;
}

}  // namespace

Edge carryLoop(const ReducedGraph& reduced, const Edge& loop) {
  const std::pair<Piece, Piece> from = pieces(reduced, loop.from), to = pieces(reduced, loop.to);
  Piece f = shorter(from), g = shorter(to);
  if (f.index == g.index) {
    // Both carried to the anchor between them: the earlier endpoint goes back, the later one forward.
    f = loop.from < loop.to ? from.first : from.second;
    g = loop.from < loop.to ? to.second : to.first;
  }
  Edge e = loop;
  e.from = f.index;
  e.to = g.index;
  if (reduced.anchors[f.index] == loop.from && reduced.anchors[g.index] == loop.to) return e;
  e.T_from_to = f.T * loop.T_from_to * g.T.inverse();
  const Matrix6d A = adjointInverse(loop.T_from_to);
  const Matrix6d B = adjointInverse(g.T.inverse());  // Ad(T̂_B_g)
  const Eigen::FullPivLU<Matrix6d> loop_lu(loop.information);
  if (!loop_lu.isInvertible()) {  // a singular loop information (a g2o file's): carried without the pieces
    const Matrix6d B_inv = adjointInverse(g.T);
    e.information = B_inv.transpose() * loop.information * B_inv;
    return e;
  }
  Matrix6d sigma = B * (A * f.covariance * A.transpose() + loop_lu.inverse() + g.covariance) * B.transpose();
  sigma = 0.5 * (sigma + sigma.transpose()).eval();
  e.information = sigma.inverse();
  e.information = 0.5 * (e.information + e.information.transpose()).eval();
  return e;
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
