/// @file ransac.h
/// @brief Rigid alignment of point correspondences: SVD (Kabsch) and seeded RANSAC (algorithm §7.2, §7.5).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc {

/// The rigid transform T (4×4) minimising Σ‖T·source_k − target_k‖², with det(R) = +1 (no reflection).
/// Needs at least one pair; source and target must have the same length.
Eigen::Matrix4d fitRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target);

/// True if the rotation of @p T turns the z axis by at most @p max_tilt (rad): cos of that angle is T(2, 2). Always
/// true for max_tilt ≥ π. RansacParams::max_tilt and guided matching apply it (algorithm §7.2).
bool isUpright(const Eigen::Matrix4d& T, double max_tilt);

struct RansacParams {
  int iterations = 500;           ///< hypotheses
  int sample_size = 7;            ///< pairs drawn per hypothesis
  bool with_replacement = true;   ///< draw with replacement (authors' code) or distinct pairs
  double inlier_threshold = 0.4;  ///< ‖T·s − t‖ < this (m)
  int min_inliers = 5;            ///< a hypothesis needs at least this many inliers ...
  double min_inlier_fraction = 0.01;  ///< ... and this share of all pairs
  /// Stop once a sample of only inliers of the best hypothesis has been drawn with this probability (adaptive
  /// RANSAC); 1 = always run every iteration, as the authors' code.
  double confidence = 0.999;
  /// A hypothesis whose rotation turns the z axis by more than this (rad) is skipped: scans of a ground vehicle are
  /// upright at both visits. π = no check.
  double max_tilt = 3.14159265358979323846;
  uint32_t seed = 42;             ///< std::mt19937 seed
};

struct RansacResult {
  bool accepted = false;                                   ///< a hypothesis met min_inliers and min_inlier_fraction
  Eigen::Matrix4d T_target_source = Eigen::Matrix4d::Identity();  ///< the best hypothesis
  std::vector<int> inliers;                                ///< indices of its inlier pairs, ascending
};

/// RANSAC over correspondences (source_k, target_k) (algorithm §7.2): keeps the hypothesis with strictly the most
/// inliers (so the first one found wins a tie) among those within `max_tilt`; stops after `iterations`, once every
/// pair is an inlier, or when the adaptive bound for `confidence` is reached. Deterministic for a given seed on every platform (no std::uniform_int_distribution).
RansacResult ransacRigid(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                         const RansacParams& params);

}  // namespace sgtllc
