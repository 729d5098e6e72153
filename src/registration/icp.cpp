// Point-to-plane ICP seeded by the object-level SVD pose (docs/registration.md).
//
// Gauss-Newton on the point-to-plane residuals r_i = n_iᵀ (R p_i + t − q_i) over a right perturbation
// T ← T · Exp(δ), δ = (δt, δθ): the tangent space of backend::Edge, so the normal matrix at the final pose is
// the loop edge's information. Sequential sums in point order keep it deterministic at any thread count.
#include "sgtllc/registration/icp.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "sgtllc/point_kdtree.h"

namespace sgtllc {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

constexpr int kMinPairs = 6;  // six unknowns
constexpr double kCoarseConvergence = 1e-3;  // m and rad: where the coarse stage hands over to the fine one
/// Query points the coarse stage pairs, at most (an even stride over the query): it only has to bring the pose
/// within the fine stage's reach, and 2,000 points fix six unknowns as well as 8,000 do there (BENCHMARKS.md,
/// "Fine registration").
constexpr size_t kCoarsePoints = 2000;

/// Unit normals of the target points from the covariance of their k nearest neighbours (smallest eigenvector),
/// or zero where the neighbourhood is a line or a point (no plane to project on). Computed on first use: the
/// dense match cloud has many points no query point ever pairs with.
class Normals {
 public:
  Normals(const std::vector<float>& rows, const PointKdTree& tree, int k)
      : rows_(rows), tree_(tree), k_(k), normal_(rows.size() / 3), done_(rows.size() / 3, 0) {}
  const Eigen::Vector3f& operator()(size_t i) {
    if (!done_[i]) {
      normal_[i] = compute(i);
      done_[i] = 1;
    }
    return normal_[i];
  }

 private:
  Eigen::Vector3f compute(size_t i);
  const std::vector<float>& rows_;
  const PointKdTree& tree_;
  int k_;
  std::vector<Eigen::Vector3f> normal_;
  std::vector<uint8_t> done_;
  std::vector<uint32_t> near_;
};

Eigen::Vector3f Normals::compute(size_t i) {
  const std::vector<float>& rows = rows_;
  std::vector<uint32_t>& near = near_;
  tree_.knn(&rows[3 * i], k_, &near);
  {
    if (near.size() < 3) return Eigen::Vector3f::Zero();
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (uint32_t j : near) mean += Eigen::Vector3f(&rows[3 * static_cast<size_t>(j)]).cast<double>();
    mean /= static_cast<double>(near.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (uint32_t j : near) {
      const Eigen::Vector3d d = Eigen::Vector3f(&rows[3 * static_cast<size_t>(j)]).cast<double>() - mean;
      cov += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(cov);
    const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
    if (!(lambda(1) > 1e-12) || lambda(1) < 1e-3 * lambda(2)) return Eigen::Vector3f::Zero();  // a line or a point
    return eig.eigenvectors().col(0).cast<float>();
  }
}

/// Normal equations of the point-to-plane residuals at @p T.
struct Linearisation {
  Matrix6d H = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
  double sum_r2 = 0.0;   ///< unweighted, for the RMSE
  double sum_wr2 = 0.0;  ///< weighted, for σ of the information
  double sum_w = 0.0;
  int pairs = 0;   ///< pairs with a plane (a target normal)
  int paired = 0;  ///< query points with a target point within the distance, with or without a plane
};

Linearisation linearise(const std::vector<Eigen::Vector3f>& query, const std::vector<float>& rows,
                        Normals& normal, const PointKdTree& tree,
                        const Eigen::Matrix4d& T, double max_distance, double kernel) {
  Linearisation lin;
  const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = T.topRightCorner<3, 1>();
  const double max_d2 = max_distance * max_distance;
  for (const Eigen::Vector3f& pf : query) {
    const Eigen::Vector3d p = pf.cast<double>();
    const Eigen::Vector3d x = R * p + t;
    const Eigen::Vector3f xf = x.cast<float>();
    const int j = tree.nearestWithin(xf.data(), max_d2).first;
    if (j < 0) continue;
    ++lin.paired;
    const Eigen::Vector3d n = normal(static_cast<size_t>(j)).cast<double>();
    if (n.isZero()) continue;
    const Eigen::Vector3d q = Eigen::Vector3f(&rows[3 * static_cast<size_t>(j)]).cast<double>();
    const double r = n.dot(x - q);
    const Eigen::Vector3d m = R.transpose() * n;  // the normal in the query frame
    Vector6d J;
    J << m, p.cross(m);
    // Cauchy weight: pairs across different surfaces (vegetation, a changed scene) have large residuals and
    // would pull the pose; the weighted least squares is the IRLS step of ρ(r) = k² log(1 + r²/k²).
    const double w = kernel > 0.0 ? 1.0 / (1.0 + (r * r) / (kernel * kernel)) : 1.0;
    lin.H.noalias() += w * J * J.transpose();
    lin.g.noalias() += w * J * r;
    lin.sum_r2 += r * r;
    lin.sum_wr2 += w * r * r;
    lin.sum_w += w;
    ++lin.pairs;
  }
  return lin;
}

/// The normal matrix is singular (or nearly) when the pairs leave a direction free: relative to its largest
/// eigenvalue, after scaling the rotation block by a 10 m lever so both blocks have units of m².
bool degenerate(const Matrix6d& H) {
  Matrix6d S = Matrix6d::Identity();
  S.bottomRightCorner<3, 3>() *= 0.1;
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(S * H * S, Eigen::EigenvaluesOnly);
  return !(eig.eigenvalues()(0) > 1e-6 * eig.eigenvalues()(5));
}

/// Why a linearisation cannot take a step: too few pairs, or a direction left free; nothing if it can.
std::optional<RefinementStatus> failure(const Linearisation& lin) {
  if (lin.pairs < kMinPairs) return RefinementStatus::kTooFewPoints;
  if (degenerate(lin.H)) return RefinementStatus::kDegenerate;
  return std::nullopt;
}

}  // namespace

const char* refinementStatusName(RefinementStatus s) {
  switch (s) {
    case RefinementStatus::kConverged: return "converged";
    case RefinementStatus::kMaxIterations: return "max_iterations";
    case RefinementStatus::kTooFewPoints: return "too_few_points";
    case RefinementStatus::kDegenerate: return "degenerate";
    case RefinementStatus::kLowFitness: return "low_fitness";
    case RefinementStatus::kMovedTooFar: return "moved_too_far";
  }
  return "unknown";
}

Refinement refinePose(const std::vector<Eigen::Vector3f>& query, const std::vector<Eigen::Vector3f>& match,
                      const Eigen::Matrix4d& T_seed, const RegistrationConfig& config) {
  const auto start = std::chrono::steady_clock::now();
  Refinement out;
  out.T_match_query_seed = T_seed;
  out.T_match_query = T_seed;
  out.query_points = static_cast<int>(query.size());
  out.match_points = static_cast<int>(match.size());
  auto finish = [&](RefinementStatus status) {
    out.status = status;
    if (!out.used()) {
      out.T_match_query = T_seed;
      out.information.setZero();
    }
    out.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
  };
  if (query.size() < kMinPairs || match.size() < kMinPairs) return finish(RefinementStatus::kTooFewPoints);

  std::vector<float> rows(3 * match.size());
  for (size_t i = 0; i < match.size(); ++i) {
    for (int d = 0; d < 3; ++d) rows[3 * i + static_cast<size_t>(d)] = match[i](d);
  }
  const PointKdTree tree(&rows);
  Normals normal(rows, tree, config.normal_neighbors);

  Eigen::Matrix4d T = T_seed;
  bool converged = false;
  // A seed from a few node centres can be a metre and some degrees off (sparse sensors, centres of walls seen
  // from the other side): a coarse stage pulls it in with far pairs, the fine stage then fits at the fine distance
  // (docs/registration.md).
  std::vector<double> stages;
  if (config.coarse_correspondence > config.max_correspondence) stages.push_back(config.coarse_correspondence);
  stages.push_back(config.max_correspondence);
  std::vector<Eigen::Vector3f> coarse_query;
  if (stages.size() > 1 && query.size() > kCoarsePoints) {
    const size_t stride = (query.size() + kCoarsePoints - 1) / kCoarsePoints;
    for (size_t i = 0; i < query.size(); i += stride) coarse_query.push_back(query[i]);
  }
  for (size_t stage = 0; stage < stages.size(); ++stage) {
    const double distance = stages[stage];
    const bool coarse = stage + 1 < stages.size();
    // The coarse stage's subsample, until it pairs too few points or leaves a direction free: then the whole query,
    // so that the subsample never fails a refinement the whole query would carry on.
    const std::vector<Eigen::Vector3f>* points = coarse && !coarse_query.empty() ? &coarse_query : &query;
    // The coarse stage only has to bring the pose into the fine stage's reach: it stops at millimetre steps.
    const double tolerance = coarse ? std::max(config.convergence, kCoarseConvergence) : config.convergence;
    converged = false;
    for (int it = 0; it < config.max_iterations && !converged; ++it) {
      Linearisation lin = linearise(*points, rows, normal, tree, T, distance, config.kernel);
      std::optional<RefinementStatus> failed = failure(lin);
      if (failed && points != &query) {
        points = &query;
        lin = linearise(query, rows, normal, tree, T, distance, config.kernel);
        failed = failure(lin);
      }
      if (failed) return finish(*failed);
      const Vector6d delta = -lin.H.ldlt().solve(lin.g);
      Eigen::Matrix4d step = Eigen::Matrix4d::Identity();
      const double angle = delta.tail<3>().norm();
      if (angle > 0.0) {
        step.topLeftCorner<3, 3>() = Eigen::AngleAxisd(angle, delta.tail<3>() / angle).toRotationMatrix();
      }
      step.topRightCorner<3, 1>() = delta.head<3>();
      T = T * step;
      ++out.iterations;
      converged = delta.head<3>().norm() < tolerance && angle < tolerance;
    }
  }
  // Re-orthonormalise: many small products drift from SO(3) in the last bits.
  const Eigen::Quaterniond q(Eigen::Matrix3d(T.topLeftCorner<3, 3>()));
  T.topLeftCorner<3, 3>() = q.normalized().toRotationMatrix();

  const Linearisation last = linearise(query, rows, normal, tree, T, config.max_correspondence, config.kernel);
  if (last.pairs < kMinPairs) return finish(RefinementStatus::kTooFewPoints);
  out.T_match_query = T;
  out.fitness = static_cast<double>(last.paired) / static_cast<double>(query.size());
  out.rmse_m = std::sqrt(last.sum_r2 / last.pairs);
  const Eigen::Matrix4d moved = T_seed.inverse() * T;
  const double moved_deg = Eigen::AngleAxisd(Eigen::Matrix3d(moved.topLeftCorner<3, 3>())).angle() * 180.0 / M_PI;
  if ((T.topRightCorner<3, 1>() - T_seed.topRightCorner<3, 1>()).norm() > config.max_translation_change ||
      moved_deg > config.max_rotation_change_deg) {
    return finish(RefinementStatus::kMovedTooFar);
  }
  if (out.fitness < config.min_fitness) return finish(RefinementStatus::kLowFitness);
  if (degenerate(last.H)) return finish(RefinementStatus::kDegenerate);
  // σ² of the weighted residuals (6 unknowns), floored: a perfect fit must not claim infinite precision.
  const double sigma2 = std::max(config.information_sigma_min * config.information_sigma_min,
                                 last.sum_wr2 / std::max(1.0, last.sum_w - 6.0));
  out.information = config.information_scale / sigma2 * last.H;
  return finish(converged ? RefinementStatus::kConverged : RefinementStatus::kMaxIterations);
}

}  // namespace sgtllc
