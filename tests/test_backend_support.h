// Simulated pose graphs for the back-end tests and benchmark: an urban drive with drifting odometry, loops fitted
// to noisy object centres (as the detector does) and random false loops. Fixed seeds throughout.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/backend/information.h"
#include "sgtllc/backend/pose_graph_types.h"
#include "sgtllc/ransac.h"

namespace sgtllc::test {

/// Pose from a position and a yaw (rad), z up.
inline Eigen::Isometry3d planarPose(const Eigen::Vector3d& p, double yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = p;
  return T;
}

/// @p frames poses 1 m apart driving a fixed 2,100 m route over a 300 m × 150 m street grid (one lap of the
/// outer streets, then the middle street and every outer street again, some in the opposite direction), over
/// gentle hills (±2 m); the route repeats for longer runs. Starts at the identity.
inline std::vector<Eigen::Isometry3d> urbanTrajectory(int frames) {
  const std::vector<Eigen::Vector2d> corners = {{0, 0},     {300, 0},   {300, 150}, {0, 150},   {0, 0},
                                                {150, 0},   {150, 150}, {300, 150}, {300, 0},   {150, 0},
                                                {150, 150}, {0, 150},   {0, 0}};
  std::vector<Eigen::Vector2d> xy;
  while (static_cast<int>(xy.size()) < frames + 1) {
    for (size_t c = 0; c + 1 < corners.size(); ++c) {
      const Eigen::Vector2d a = corners[c], b = corners[c + 1];
      const int steps = static_cast<int>(std::round((b - a).norm()));
      for (int s = 0; s < steps; ++s) xy.push_back(a + (b - a) * (static_cast<double>(s) / steps));
    }
  }
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < frames; ++i) {
    const Eigen::Vector2d next = xy[i + 1], prev = xy[i > 0 ? i - 1 : 0];
    const double yaw = std::atan2(next.y() - prev.y(), next.x() - prev.x());
    const double z = 2.0 * std::sin(xy[i].x() / 90.0) * std::cos(xy[i].y() / 110.0);
    poses.push_back(planarPose({xy[i].x(), xy[i].y(), z}, yaw));
  }
  const Eigen::Isometry3d T0_inv = poses[0].inverse();
  for (auto& T : poses) T = T0_inv * T;
  return poses;
}

/// Small rotation from a rotation vector.
inline Eigen::Matrix3d expSO3(const Eigen::Vector3d& w) {
  const double a = w.norm();
  return a < 1e-15 ? Eigen::Matrix3d::Identity() : Eigen::AngleAxisd(a, w / a).toRotationMatrix();
}

/// Odometry of @p truth with a systematic drift (yaw bias per metre, scale error) and random per-step noise.
inline std::vector<Eigen::Isometry3d> driftingOdometry(const std::vector<Eigen::Isometry3d>& truth, unsigned seed,
                                                       double yaw_bias_per_m = 4.0e-5, double scale_error = 0.001,
                                                       double sigma_t = 0.01, double sigma_r = 2.0e-4) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<Eigen::Isometry3d> odometry{truth[0]};
  for (size_t i = 1; i < truth.size(); ++i) {
    Eigen::Isometry3d step = truth[i - 1].inverse() * truth[i];
    const double d = step.translation().norm();
    // One draw per statement, last component first: the order of draws in one expression is unspecified, and a
    // fixed order keeps the drive the same with every compiler (include/sgtllc/sim/rng.h).
    const double wz = n01(rng), wy = n01(rng), wx = n01(rng);
    const Eigen::Vector3d w(sigma_r * wx, sigma_r * wy, sigma_r * wz + yaw_bias_per_m * d);
    const double tz = n01(rng), ty = n01(rng), tx = n01(rng);
    const Eigen::Vector3d dt(sigma_t * tx, sigma_t * ty, sigma_t * tz);
    step.translation() = (1.0 + scale_error) * step.translation() + dt;
    step.linear() = step.linear() * expSO3(w);
    odometry.push_back(odometry.back() * step);
  }
  return odometry;
}

/// A loop as the detector makes it: @p n object centres around the query frame, seen from the match frame with
/// per-axis noise @p sigma, the pose fitted to them (Kabsch) and its information from the fit.
inline backend::Edge fittedLoop(int match, int query, const Eigen::Isometry3d& T_match_query_true, std::mt19937& rng,
                                const backend::LoopNoise& noise, int n = 15, double sigma = 0.1) {
  std::uniform_real_distribution<double> u(-25.0, 25.0);
  std::uniform_real_distribution<double> uz(-1.0, 3.0);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<Eigen::Vector3d> query_centres, match_centres;
  for (int k = 0; k < n; ++k) {
    const double sz = uz(rng), sy = u(rng), sx = u(rng);  // one draw per statement (see above)
    const Eigen::Vector3d s(sx, sy, sz);
    query_centres.push_back(s);
    const double nz = n01(rng), ny = n01(rng), nx = n01(rng);
    match_centres.push_back(T_match_query_true * s + sigma * Eigen::Vector3d(nx, ny, nz));
  }
  backend::Edge e;
  e.from = match;
  e.to = query;
  e.T_from_to = Eigen::Isometry3d(fitRigid(query_centres, match_centres));
  e.information = backend::loopInformation(query_centres, match_centres, e.T_from_to, noise);
  e.kind = backend::EdgeKind::kLoop;
  return e;
}

/// True loops: for every @p every-th query frame, the closest earlier frame at least @p min_gap frames back and
/// within @p radius metres (ground truth), fitted with fittedLoop.
inline std::vector<backend::Edge> trueLoops(const std::vector<Eigen::Isometry3d>& truth, unsigned seed,
                                            const backend::LoopNoise& noise, int every = 10, int min_gap = 100,
                                            double radius = 3.0) {
  std::mt19937 rng(seed);
  std::vector<backend::Edge> loops;
  for (int q = min_gap; q < static_cast<int>(truth.size()); q += every) {
    int best = -1;
    double best_d = radius;
    for (int m = 0; m + min_gap <= q; ++m) {
      const double d = (truth[m].translation() - truth[q].translation()).norm();
      if (d < best_d) {
        best_d = d;
        best = m;
      }
    }
    if (best >= 0) loops.push_back(fittedLoop(best, q, truth[best].inverse() * truth[q], rng, noise));
  }
  return loops;
}

/// @p count false loops: random frame pairs more than 50 m apart (ground truth) with random poses (yaw anywhere,
/// translation within ±5 m), fitted like a real loop so their information looks as confident.
inline std::vector<backend::Edge> falseLoops(const std::vector<Eigen::Isometry3d>& truth, int count, unsigned seed,
                                             const backend::LoopNoise& noise) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> frame(0, static_cast<int>(truth.size()) - 1);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI), t(-5.0, 5.0);
  std::vector<backend::Edge> loops;
  while (static_cast<int>(loops.size()) < count) {
    int a = frame(rng), b = frame(rng);
    if ((truth[a].translation() - truth[b].translation()).norm() <= 50.0) continue;
    if (a > b) std::swap(a, b);
    const double heading = yaw(rng);  // drawn before the translation, in its own statement (see above)
    const Eigen::Vector3d offset{t(rng), t(rng), 0.1 * t(rng)};  // a braced list is evaluated in order
    loops.push_back(fittedLoop(a, b, planarPose(offset, heading), rng, noise));
  }
  return loops;
}

/// Absolute trajectory error: RMSE of the positions after the best rigid alignment onto @p truth (m).
inline double ate(const std::vector<Eigen::Isometry3d>& estimate, const std::vector<Eigen::Isometry3d>& truth) {
  std::vector<Eigen::Vector3d> e, t;
  for (size_t i = 0; i < truth.size(); ++i) {
    e.push_back(estimate[i].translation());
    t.push_back(truth[i].translation());
  }
  const Eigen::Matrix4d T = fitRigid(e, t);
  double sum = 0.0;
  for (size_t i = 0; i < e.size(); ++i) {
    sum += (T.topLeftCorner<3, 3>() * e[i] + T.topRightCorner<3, 1>() - t[i]).squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(e.size()));
}

}  // namespace sgtllc::test
