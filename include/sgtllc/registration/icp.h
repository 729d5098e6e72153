/// @file icp.h
/// @brief Point-to-plane ICP that refines a loop's pose, with its checks and its information matrix
///        (docs/registration.md).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "sgtllc/config/registration_config.h"

namespace sgtllc {

/// How a refinement ended. Only kConverged and kMaxIterations replace the seed pose.
enum class RefinementStatus {
  kConverged,      ///< an update smaller than RegistrationConfig::convergence; the checks passed
  kMaxIterations,  ///< max_iterations reached without convergence; the checks passed
  kTooFewPoints,   ///< fewer than 6 points in either cloud or fewer than 6 pairs: nothing to fit
  kDegenerate,     ///< the pairs leave a direction unconstrained (e.g. one plane): the normal matrix is singular
  kLowFitness,     ///< share of paired source points at the end below min_fitness: too little overlap
  kMovedTooFar,    ///< moved the seed by more than max_translation_change or max_rotation_change_deg: diverged
};

/// "converged", "max_iterations", "too_few_points", "degenerate", "low_fitness" or "moved_too_far".
const char* refinementStatusName(RefinementStatus s);

/// Outcome of refining T_match_query (p_match = T · p_query) from a seed.
struct Refinement {
  RefinementStatus status = RefinementStatus::kTooFewPoints;
  Eigen::Matrix4d T_match_query_seed = Eigen::Matrix4d::Identity();  ///< the seed (the object-level SVD pose)
  /// The refined pose if used(), else the seed (the fallback).
  Eigen::Matrix4d T_match_query = Eigen::Matrix4d::Identity();
  int iterations = 0;          ///< Gauss-Newton steps taken
  double fitness = 0.0;        ///< share of query points paired within max_correspondence at the final pose [0, 1]
  double rmse_m = 0.0;         ///< RMS point-to-plane distance of those pairs (m)
  int query_points = 0;        ///< points of the query (source) cloud
  int match_points = 0;        ///< points of the match (target) cloud
  /// 6×6 information over (δt in m, δθ in rad) of a right perturbation in the query frame, T · Exp(δ): the
  /// convention of backend::Edge for the loop edge match → query. Zero unless used().
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
  double time_ms = 0.0;        ///< wall-clock time of the refinement (normals included)

  /// Whether the refined pose replaced the seed.
  bool used() const { return status == RefinementStatus::kConverged || status == RefinementStatus::kMaxIterations; }
};

/// Refines @p T_seed by point-to-plane ICP of @p query onto @p match (normals of @p match from its
/// config.normal_neighbors nearest points), then checks fitness and the distance moved; on any failure the seed is
/// kept and the status says why. Sequential and a pure function of its inputs (deterministic).
Refinement refinePose(const std::vector<Eigen::Vector3f>& query, const std::vector<Eigen::Vector3f>& match,
                      const Eigen::Matrix4d& T_seed, const RegistrationConfig& config);

}  // namespace sgtllc
