/// @file odometry.h
/// @brief A drifting odometry estimate of a simulated drive, so the pose-graph back end can be measured on every
///        simulated sequence as on real LiDAR odometry (KISS-ICP on KITTI 00 drifts by metres).
///
/// The model, per frame step k (frame k−1 → k, in the LiDAR frame of k−1): the true relative motion
/// (R_k, t_k), with step length d_k = ‖t_k‖, becomes
///
///     t̃_k = (1 + b + σ_s·n_k) · t_k              translation: a per-sequence scale error b = σ_b·n_b plus
///                                                  white per-step scale noise
///     R̃_k = Rz(ψ_k) · R_k,  ψ_k = σ_ψ·√d_k·m_k     yaw: a random walk in heading per metre driven
///
/// with n_b, n_k, m_k standard normal clamped to ±3 (so every step's error is bounded), T̃_0 = T_0 and
/// T̃_k = T̃_{k−1} · [R̃_k | t̃_k]. A standing sensor (d_k = 0) does not drift in yaw. After a path of length D
/// the heading error has a standard deviation of σ_ψ·√D, the lateral position error about σ_ψ·√(D³/3) on a
/// straight path and the along-track error |b|·D: with the defaults, an RMS end-point error of about 2 % of the
/// distance at 1 km and 3 % at 2 km. One seed can be well below or above that: a 2,000-frame urban sequence
/// (seed 3, 1.74 km) drifts by at most 4.9 m, similar to KISS-ICP on KITTI 00 (at most 15 m over 3.7 km).
/// Roll, pitch and the vertical motion stay exact, as for odometry aided by a gravity-aligned IMU.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::sim {

/// Noise of the drifting odometry (see the file comment for the model).
struct OdometryNoise {
  double scale_bias_sigma = 0.01;  ///< σ_b: standard deviation of the per-sequence scale error b (1 = 100 %)
  double scale_sigma = 0.02;       ///< σ_s: white per-step scale noise (relative)
  double yaw_walk = 1.0e-3;        ///< σ_ψ: heading random walk (rad per √m driven)

  /// The defaults multiplied by @p factor (0 = the true motion, accumulated: exact up to rounding).
  /// Throws sgtllc::Error if factor < 0 or not finite.
  static OdometryNoise scaled(double factor);
};

/// The odometry estimate of the poses @p T_0_i (each frame's pose in frame 0, so T_0_0 = I; any common frame
/// works): element 0 equals @p T_0_i[0], every later pose accumulates the noisy relative motions. Random numbers
/// come from the simulator's own odometry stream of @p seed, so no other simulator output changes with it.
std::vector<Eigen::Matrix4d> driftingOdometry(const std::vector<Eigen::Matrix4d>& T_0_i, const OdometryNoise& noise,
                                              uint64_t seed);

}  // namespace sgtllc::sim
