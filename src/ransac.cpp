#include "sgtllc/ransac.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <Eigen/LU>
#include <Eigen/SVD>

namespace sgtllc {
namespace {

/// Uniform index in [0, n) from one 32-bit draw (multiply-shift; bias below 2⁻²⁰ for n < 4096).
uint32_t drawIndex(std::mt19937& rng, uint32_t n) {
  return static_cast<uint32_t>((static_cast<uint64_t>(rng()) * n) >> 32);
}

void drawSample(std::mt19937& rng, int n, const RansacParams& params, std::vector<int>* sample,
                std::vector<int>* scratch) {
  sample->clear();
  if (params.with_replacement) {
    for (int s = 0; s < params.sample_size; ++s) sample->push_back(static_cast<int>(drawIndex(rng, n)));
    return;
  }
  // Partial Fisher–Yates over a fresh index list: distinct pairs.
  scratch->resize(n);
  for (int k = 0; k < n; ++k) (*scratch)[k] = k;
  const int size = std::min(params.sample_size, n);
  for (int s = 0; s < size; ++s) {
    const int pick = s + static_cast<int>(drawIndex(rng, static_cast<uint32_t>(n - s)));
    std::swap((*scratch)[s], (*scratch)[pick]);
    sample->push_back((*scratch)[s]);
  }
}

/// Kabsch on the pairs listed in @p idx (repeats allowed): centre both sets, H = Σ s̃ t̃ᵀ = UΣVᵀ,
/// R = V·diag(1, 1, det(VUᵀ))·Uᵀ, t = μ_t − R μ_s. The det-sign correction keeps R a rotation, which the authors'
/// code omits (algorithm §7.2). Fixed-size and allocation-free: RANSAC calls it 500 times per candidate, where
/// Eigen::umeyama's dynamic-size path measured about three times slower.
Eigen::Matrix4d kabsch(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                       const std::vector<int>& idx) {
  Eigen::Vector3d mu_s = Eigen::Vector3d::Zero(), mu_t = Eigen::Vector3d::Zero();
  for (int k : idx) {
    mu_s += source[k];
    mu_t += target[k];
  }
  mu_s /= static_cast<double>(idx.size());
  mu_t /= static_cast<double>(idx.size());
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  for (int k : idx) H += (source[k] - mu_s) * (target[k] - mu_t).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = svd.matrixV() * D * svd.matrixU().transpose();
  T.topRightCorner<3, 1>() = mu_t - T.topLeftCorner<3, 3>() * mu_s;
  return T;
}

/// A rigid motion keeps distances, so two pairs that are both inliers (each within the threshold r of its target)
/// have source and target distances that differ by less than 2r. A minimal sample (three pairs) that fails this
/// cannot be all inliers, and its exact fit is then a wrong hypothesis: it is skipped before the SVD. Most
/// samples of a wrong candidate fail it, which is most of RANSAC's time (BENCHMARKS.md "Association and RANSAC
/// sample"). A larger sample is not checked: its least-squares fit can still be right with one outlier in it.
bool distancesAgree(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                    const std::vector<int>& sample, double threshold) {
  for (size_t a = 0; a < sample.size(); ++a) {
    for (size_t b = a + 1; b < sample.size(); ++b) {
      const double ds = (source[sample[a]] - source[sample[b]]).norm();
      const double dt = (target[sample[a]] - target[sample[b]]).norm();
      if (std::abs(ds - dt) >= 2.0 * threshold) return false;
    }
  }
  return true;
}

/// Hypotheses after which a sample of only inliers (of the best hypothesis so far) has been drawn with probability
/// `confidence`: log(1 − confidence) / log(1 − P(all-inlier sample)). Unlimited for confidence ≥ 1.
int iterationsNeeded(int inliers, int n, const RansacParams& params) {
  if (params.confidence >= 1.0) return std::numeric_limits<int>::max();
  double p_good = 1.0;
  for (int s = 0; s < params.sample_size; ++s) {
    p_good *= params.with_replacement ? static_cast<double>(inliers) / n
                                      : std::max(0.0, static_cast<double>(inliers - s) / (n - s));
  }
  if (p_good >= 1.0) return 1;
  // log1p keeps tiny probabilities (7 draws at a low inlier share underflow 1 − p_good to 1) from giving log 0.
  const double k = std::ceil(std::log1p(-params.confidence) / std::log1p(-p_good));
  if (!(k < std::numeric_limits<int>::max())) return std::numeric_limits<int>::max();  // also p_good = 0 (NaN/inf)
  return std::max(1, static_cast<int>(k));
}

/// The least T(2, 2) = cos(tilt) within @p max_tilt; below −1 (no rotation refused) for max_tilt ≥ π.
double minUpCosine(double max_tilt) { return max_tilt >= M_PI ? -2.0 : std::cos(max_tilt); }

}  // namespace

bool isUpright(const Eigen::Matrix4d& T, double max_tilt) { return T(2, 2) >= minUpCosine(max_tilt); }

Eigen::Matrix4d fitRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target) {
  if (source.size() != target.size() || source.empty()) {
    throw std::invalid_argument("fitRigid: need the same, non-zero number of source and target points");
  }
  std::vector<int> all(source.size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
  return kabsch(source, target, all);
}

RansacResult ransacRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                         const RansacParams& params) {
  if (source.size() != target.size()) throw std::invalid_argument("ransacRigid: source and target differ in size");
  RansacResult result;
  const int n = static_cast<int>(source.size());
  if (n == 0) return result;
  std::mt19937 rng(params.seed);
  const double thr2 = params.inlier_threshold * params.inlier_threshold;
  std::vector<int> sample, scratch;
  int best_count = 0;
  int needed = params.iterations;
  const bool check_sample = params.sample_size <= 3;
  // isUpright with its cosine computed once: hundreds of hypotheses per candidate.
  const double min_up_cos = minUpCosine(params.max_tilt);
  for (int it = 0; it < std::min(params.iterations, needed) && best_count < n; ++it) {
    drawSample(rng, n, params, &sample, &scratch);
    if (check_sample && !distancesAgree(source, target, sample, params.inlier_threshold)) continue;
    const Eigen::Matrix4d T = kabsch(source, target, sample);
    const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
    if (R(2, 2) < min_up_cos) continue;
    const Eigen::Vector3d t = T.topRightCorner<3, 1>();
    int count = 0;
    for (int k = 0; k < n; ++k) count += ((R * source[k] + t - target[k]).squaredNorm() < thr2);
    if (count > best_count) {
      best_count = count;
      result.T_target_source = T;
      needed = iterationsNeeded(best_count, n, params);
    }
  }
  result.accepted = best_count > 0 && best_count >= params.min_inliers &&
                    best_count >= params.min_inlier_fraction * n;
  if (best_count > 0) {
    const Eigen::Matrix3d R = result.T_target_source.topLeftCorner<3, 3>();
    const Eigen::Vector3d t = result.T_target_source.topRightCorner<3, 1>();
    for (int k = 0; k < n; ++k) {
      if ((R * source[k] + t - target[k]).squaredNorm() < thr2) result.inliers.push_back(k);
    }
  }
  return result;
}

}  // namespace sgtllc
