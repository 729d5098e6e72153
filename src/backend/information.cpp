#include "sgtllc/backend/information.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Eigenvalues>

namespace sgtllc::backend {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return s;
}

}  // namespace

Matrix6d odometryInformation(const Eigen::Isometry3d& T_prev_curr, const OdometryNoise& noise) {
  const double d = T_prev_curr.translation().norm();
  const double theta = Eigen::AngleAxisd(T_prev_curr.rotation()).angle();
  const double var_t = noise.translation_sigma_min * noise.translation_sigma_min +
                       std::pow(noise.translation_sigma_per_m * d, 2);
  const double var_r = noise.rotation_sigma_min * noise.rotation_sigma_min +
                       std::pow(noise.rotation_sigma_per_m * d, 2) + std::pow(noise.rotation_sigma_per_rad * theta, 2);
  Matrix6d information = Matrix6d::Zero();
  information.diagonal() << Eigen::Vector3d::Constant(1.0 / var_t), Eigen::Vector3d::Constant(1.0 / var_r);
  return information;
}

std::vector<Edge> odometryEdges(const std::vector<Eigen::Isometry3d>& odometry, const OdometryNoise& noise) {
  std::vector<Edge> edges;
  for (size_t i = 1; i < odometry.size(); ++i) {
    Edge e;
    e.from = static_cast<int>(i - 1);
    e.to = static_cast<int>(i);
    e.T_from_to = odometry[i - 1].inverse() * odometry[i];
    e.information = odometryInformation(e.T_from_to, noise);
    e.kind = EdgeKind::kOdometry;
    edges.push_back(e);
  }
  return edges;
}

PoseGraph odometryGraph(const std::vector<Eigen::Isometry3d>& odometry, const OdometryNoise& noise) {
  PoseGraph graph;
  graph.poses = odometry;
  graph.edges = odometryEdges(odometry, noise);
  return graph;
}

Matrix6d loopInformation(const std::vector<Eigen::Vector3d>& query_centres,
                         const std::vector<Eigen::Vector3d>& match_centres, const Eigen::Isometry3d& T_match_query,
                         const LoopNoise& noise) {
  const size_t n = query_centres.size();
  if (match_centres.size() != n) {
    throw Error("loop information: " + std::to_string(n) + " query centres but " +
                std::to_string(match_centres.size()) + " match centres");
  }
  if (n < 3) throw Error("loop information: needs at least 3 inlier pairs, got " + std::to_string(n));
  double sum_r2 = 0.0;
  Matrix6d fisher = Matrix6d::Zero();
  for (size_t i = 0; i < n; ++i) {
    sum_r2 += (T_match_query * query_centres[i] - match_centres[i]).squaredNorm();
    // Jacobian of the residual w.r.t. a right perturbation (δt, δθ) of T_match_query, rotated back by Rᵀ
    // (which cancels in JᵀJ): [I  −[s]×].
    Eigen::Matrix<double, 3, 6> J;
    J << Eigen::Matrix3d::Identity(), -skew(query_centres[i]);
    fisher.noalias() += J.transpose() * J;
  }
  const double dof = std::max(1.0, 3.0 * static_cast<double>(n) - 6.0);
  const double var = std::max(noise.sigma_min * noise.sigma_min, sum_r2 / dof);
  const Matrix6d information = (noise.information_scale / var) * fisher;
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(information);
  if (!(eig.eigenvalues()(0) > 1e-9 * eig.eigenvalues()(5))) {
    throw Error("loop information: the " + std::to_string(n) +
                " inlier centres are collinear, so the rotation about their line is unobservable");
  }
  return information;
}

Matrix6d loopInformation(const MatchResult& match, const std::vector<Node>& query_nodes,
                         const std::vector<Node>& match_nodes, const LoopNoise& noise) {
  std::vector<Eigen::Vector3d> query_centres;
  std::vector<Eigen::Vector3d> match_centres;
  for (int k : match.inliers) {
    if (k < 0 || k >= static_cast<int>(match.associations.size())) {
      throw Error("loop information: inlier index " + std::to_string(k) + " outside the " +
                  std::to_string(match.associations.size()) + " associations");
    }
    const NodeMatch& a = match.associations[k];
    if (a.query < 0 || a.query >= static_cast<int>(query_nodes.size()) || a.match < 0 ||
        a.match >= static_cast<int>(match_nodes.size())) {
      throw Error("loop information: association " + std::to_string(k) + " names a node outside the frames");
    }
    query_centres.push_back(query_nodes[a.query].centre);
    match_centres.push_back(match_nodes[a.match].centre);
  }
  return loopInformation(query_centres, match_centres, Eigen::Isometry3d(match.T_match_query), noise);
}

Edge loopEdge(int match_frame, int query_frame, const MatchResult& match, const std::vector<Node>& query_nodes,
              const std::vector<Node>& match_nodes, const LoopNoise& noise) {
  Edge e;
  e.from = match_frame;
  e.to = query_frame;
  e.T_from_to = Eigen::Isometry3d(match.T_match_query);
  e.information = loopInformation(match, query_nodes, match_nodes, noise);
  e.kind = EdgeKind::kLoop;
  return e;
}

}  // namespace sgtllc::backend
