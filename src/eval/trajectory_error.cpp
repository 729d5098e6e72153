// Trajectory errors (trajectory_error.h): ATE with SE(3) Umeyama alignment, RPE, KITTI segment errors.
#include "sgtllc/eval/trajectory_error.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "sgtllc/types.h"

namespace sgtllc::eval {
namespace {

void checkSizes(const std::vector<Eigen::Isometry3d>& ground_truth, const std::vector<Eigen::Isometry3d>& estimate) {
  if (ground_truth.size() != estimate.size()) {
    throw Error("trajectory error: ground truth has " + std::to_string(ground_truth.size()) +
                " poses, the estimate " + std::to_string(estimate.size()) + " (one pose per frame each)");
  }
}

std::vector<Eigen::Vector3d> positions(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Vector3d> p;
  p.reserve(poses.size());
  for (const Eigen::Isometry3d& T : poses) p.push_back(T.translation());
  return p;
}

/// G⁻¹·P with the full matrix inverse: poses converted through KITTI's Tr are orthonormal only to ~1e-9, so the
/// transpose shortcut of Isometry3d::inverse would add an error of that size.
Eigen::Matrix4d relative(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return a.matrix().inverse() * b.matrix();
}

/// E = (G_a⁻¹ G_b)⁻¹ (P_a⁻¹ P_b): the estimate's relative motion seen from the ground truth's.
Eigen::Matrix4d relativeError(const std::vector<Eigen::Isometry3d>& gt, const std::vector<Eigen::Isometry3d>& est,
                              size_t a, size_t b) {
  return relative(gt[a], gt[b]).inverse() * relative(est[a], est[b]);
}

}  // namespace

ErrorStats errorStats(std::vector<double> errors) {
  ErrorStats s;
  s.count = errors.size();
  if (errors.empty()) return s;
  double sum = 0.0, sum_sq = 0.0;
  for (double e : errors) {
    sum += e;
    sum_sq += e * e;
    s.max = std::max(s.max, e);
  }
  const double n = static_cast<double>(errors.size());
  s.mean = sum / n;
  s.rmse = std::sqrt(sum_sq / n);
  std::sort(errors.begin(), errors.end());
  const size_t mid = errors.size() / 2;
  s.median = errors.size() % 2 ? errors[mid] : 0.5 * (errors[mid - 1] + errors[mid]);
  return s;
}

double rotationAngleDeg(const Eigen::Matrix3d& R) {
  const Eigen::Vector3d axis(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));  // 2 sin θ · unit axis
  return std::atan2(0.5 * axis.norm(), 0.5 * (R.trace() - 1.0)) * 180.0 / M_PI;
}

Eigen::Isometry3d alignRigid(const std::vector<Eigen::Vector3d>& src, const std::vector<Eigen::Vector3d>& dst) {
  if (src.size() != dst.size() || src.empty()) {
    throw Error("alignment needs two equally long, non-empty point lists (got " + std::to_string(src.size()) +
                " and " + std::to_string(dst.size()) + ")");
  }
  Eigen::Matrix3Xd s(3, static_cast<Eigen::Index>(src.size())), d(3, static_cast<Eigen::Index>(dst.size()));
  for (size_t i = 0; i < src.size(); ++i) {
    s.col(static_cast<Eigen::Index>(i)) = src[i];
    d.col(static_cast<Eigen::Index>(i)) = dst[i];
  }
  Eigen::Isometry3d T;
  T.matrix() = Eigen::umeyama(s, d, /*with_scaling=*/false);
  return T;
}

AteResult absoluteTrajectoryError(const std::vector<Eigen::Isometry3d>& ground_truth,
                                  const std::vector<Eigen::Isometry3d>& estimate) {
  checkSizes(ground_truth, estimate);
  if (ground_truth.empty()) throw Error("trajectory error: no poses");
  const std::vector<Eigen::Vector3d> g = positions(ground_truth), p = positions(estimate);
  AteResult r;
  r.T_gt_est = alignRigid(p, g);
  std::vector<double> aligned(g.size()), unaligned(g.size());
  for (size_t i = 0; i < g.size(); ++i) {
    aligned[i] = (g[i] - r.T_gt_est * p[i]).norm();
    unaligned[i] = (g[i] - p[i]).norm();
  }
  r.aligned = errorStats(std::move(aligned));
  r.unaligned = errorStats(std::move(unaligned));
  return r;
}

RpeResult relativePoseError(const std::vector<Eigen::Isometry3d>& ground_truth,
                            const std::vector<Eigen::Isometry3d>& estimate, int delta_frames) {
  checkSizes(ground_truth, estimate);
  if (delta_frames < 1) throw Error("relative pose error: the frame step must be ≥ 1, not " + std::to_string(delta_frames));
  RpeResult r;
  r.delta_frames = delta_frames;
  const size_t delta = static_cast<size_t>(delta_frames);
  std::vector<double> t, rot;
  for (size_t i = 0; i + delta < ground_truth.size(); ++i) {
    const Eigen::Matrix4d E = relativeError(ground_truth, estimate, i, i + delta);
    t.push_back(E.topRightCorner<3, 1>().norm());
    rot.push_back(rotationAngleDeg(E.topLeftCorner<3, 3>()));
  }
  r.translation_m = errorStats(std::move(t));
  r.rotation_deg = errorStats(std::move(rot));
  return r;
}

SegmentError kittiSegmentError(const std::vector<Eigen::Isometry3d>& ground_truth,
                               const std::vector<Eigen::Isometry3d>& estimate, const std::vector<double>& lengths_m,
                               int step_frames) {
  checkSizes(ground_truth, estimate);
  if (step_frames < 1) throw Error("segment error: the frame step must be ≥ 1, not " + std::to_string(step_frames));
  // Path length along the ground truth from frame 0 (the devkit's trajectoryDistances).
  std::vector<double> dist(ground_truth.size(), 0.0);
  for (size_t i = 1; i < ground_truth.size(); ++i) {
    dist[i] = dist[i - 1] + (ground_truth[i].translation() - ground_truth[i - 1].translation()).norm();
  }
  SegmentError s;
  double t_sum = 0.0, r_sum = 0.0;
  for (size_t first = 0; first < ground_truth.size(); first += static_cast<size_t>(step_frames)) {
    for (double length : lengths_m) {
      // The devkit's lastFrameFromSegmentLength: the first frame strictly farther than the length.
      const auto it = std::upper_bound(dist.begin() + static_cast<std::ptrdiff_t>(first), dist.end(),
                                       dist[first] + length);
      if (it == dist.end()) continue;
      const size_t last = static_cast<size_t>(it - dist.begin());
      const Eigen::Matrix4d E = relativeError(ground_truth, estimate, first, last);
      t_sum += E.topRightCorner<3, 1>().norm() / length;
      r_sum += rotationAngleDeg(E.topLeftCorner<3, 3>()) / length;
      ++s.segments;
    }
  }
  if (s.segments > 0) {
    s.translation_percent = 100.0 * t_sum / static_cast<double>(s.segments);
    s.rotation_deg_per_100m = 100.0 * r_sum / static_cast<double>(s.segments);
  }
  return s;
}

}  // namespace sgtllc::eval
