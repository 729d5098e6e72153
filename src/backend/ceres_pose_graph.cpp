#include "ceres_pose_graph.h"

#include <array>
#include <memory>

#include <ceres/ceres.h>
#include <ceres/rotation.h>

namespace sgtllc::backend::internal {
namespace {

// Pose parameter block: quaternion (x, y, z, w; Eigen's memory order) then translation.
using PoseBlock = std::array<double, 7>;
using PoseManifold = ceres::ProductManifold<ceres::EigenQuaternionManifold, ceres::EuclideanManifold<3>>;

PoseBlock toBlock(const Eigen::Isometry3d& T) {
  const Eigen::Quaterniond q(T.rotation());
  return {q.x(), q.y(), q.z(), q.w(), T.translation().x(), T.translation().y(), T.translation().z()};
}

Eigen::Isometry3d fromBlock(const PoseBlock& b) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(b[3], b[0], b[1], b[2]).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(b[4], b[5], b[6]);
  return T;
}

// Whitened edge error U·e with Ω = UᵀU.
class RelativePoseCost {
 public:
  explicit RelativePoseCost(const Edge& edge)
      : q_measured_inv_(Eigen::Quaterniond(edge.T_from_to.rotation()).conjugate()),
        t_measured_(edge.T_from_to.translation()),
        sqrt_information_(edge.information.llt().matrixU()) {}

  template <typename T>
  bool operator()(const T* from, const T* to, T* residual) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q_from(from);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_from(from + 4);
    const Eigen::Map<const Eigen::Quaternion<T>> q_to(to);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_to(to + 4);
    const Eigen::Quaternion<T> q_from_inv = q_from.conjugate();
    // X = T_from⁻¹ T_to, then Δ = Z⁻¹ X.
    const Eigen::Quaternion<T> q_x = q_from_inv * q_to;
    const Eigen::Matrix<T, 3, 1> t_x = q_from_inv * (t_to - t_from);
    const Eigen::Quaternion<T> q_m = q_measured_inv_.template cast<T>();
    const Eigen::Quaternion<T> q_delta = q_m * q_x;
    Eigen::Matrix<T, 6, 1> e;
    e.template head<3>() = q_m * (t_x - t_measured_.template cast<T>());
    const T wxyz[4] = {q_delta.w(), q_delta.x(), q_delta.y(), q_delta.z()};
    T angle_axis[3];
    ceres::QuaternionToAngleAxis(wxyz, angle_axis);
    e.template tail<3>() << angle_axis[0], angle_axis[1], angle_axis[2];
    Eigen::Map<Eigen::Matrix<T, 6, 1>> r(residual);
    r = sqrt_information_.template cast<T>() * e;
    return true;
  }

 private:
  Eigen::Quaterniond q_measured_inv_;
  Eigen::Vector3d t_measured_;
  Matrix6d sqrt_information_;
};

ceres::LossFunction* makeLoss(const BackendConfig& config) {
  const double a = config.loss_scale;
  switch (config.loop_loss) {
    case RobustLoss::kHuber: return new ceres::HuberLoss(a);
    case RobustLoss::kCauchy: return new ceres::CauchyLoss(a);
    case RobustLoss::kNone: break;
  }
  return nullptr;
}

}  // namespace

Eigen::Matrix<double, 6, 1> edgeError(const Edge& edge, const Eigen::Isometry3d& T_world_from,
                                      const Eigen::Isometry3d& T_world_to) {
  const Eigen::Isometry3d delta = edge.T_from_to.inverse() * T_world_from.inverse() * T_world_to;
  const Eigen::AngleAxisd aa(delta.rotation());
  Eigen::Matrix<double, 6, 1> e;
  e << delta.translation(), aa.angle() * aa.axis();
  return e;
}

SolveSummary solve(const std::vector<Edge>& odometry, const std::vector<Edge>& loops,
                   std::vector<Eigen::Isometry3d>& poses, const BackendConfig& config) {
  std::vector<PoseBlock> blocks(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) blocks[i] = toBlock(poses[i]);

  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  PoseManifold manifold;
  auto addEdge = [&](const Edge& edge, ceres::LossFunction* loss) {
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseCost, 6, 7, 7>(new RelativePoseCost(edge));
    problem.AddResidualBlock(cost, loss, blocks[edge.from].data(), blocks[edge.to].data());
  };
  for (const Edge& e : odometry) addEdge(e, nullptr);
  for (const Edge& e : loops) addEdge(e, makeLoss(config));
  for (auto& b : blocks) {
    if (problem.HasParameterBlock(b.data())) problem.SetManifold(b.data(), &manifold);
  }
  if (!blocks.empty() && problem.HasParameterBlock(blocks[0].data())) problem.SetParameterBlockConstant(blocks[0].data());

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.num_threads = config.solver.num_threads;
  options.max_num_iterations = config.solver.max_iterations;
  options.function_tolerance = config.solver.function_tolerance;
  options.parameter_tolerance = config.solver.parameter_tolerance;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  for (size_t i = 0; i < poses.size(); ++i) poses[i] = fromBlock(blocks[i]);
  SolveSummary out;
  out.iterations = static_cast<int>(summary.iterations.size());
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  return out;
}

}  // namespace sgtllc::backend::internal
