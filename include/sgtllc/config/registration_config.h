/// @file registration_config.h
/// @brief Settings of the fine registration that refines a loop's object-level SVD pose
///        (docs/registration.md).
#pragma once

#include <cstdint>
#include <vector>

namespace sgtllc {

/// Point-to-plane ICP on the stable-class points of both scans, seeded by the SVD pose of verification.
/// YAML keys `registration.NAME`; ranges in the settings table (settings.h).
struct RegistrationConfig {
  /// Refine the pose of comparePair (`sgtllc pair`) when both inputs are labelled scans (node input has no points).
  bool pair = true;
  /// Refine the pose of the online detector's declared loop (the chosen candidate only). Keeps a compact cloud of
  /// every frame: at most match_max_points points of 6 bytes (int16 centimetres) per frame.
  bool online = false;
  /// Raw label ids (labels.preset's convention, 0..65535) whose points join the stable-class points in the
  /// registration clouds only (never the graph). Default: SemanticKITTI's road 40, parking 44, sidewalk 48 and
  /// other-ground 49 (the geometric labeller writes its ground as 40). Walls, trunks and poles fix x, y and yaw but
  /// barely height, roll and pitch; the ground fixes those (docs/registration.md, "Points"). Empty = the stable
  /// classes alone. Set the ground ids of other presets here.
  std::vector<uint32_t> ground_ids = {40, 44, 48, 49};
  /// Voxel leaf (m) of the query (source) scan's points: the points that are moved, max_points of them. A coarse
  /// voxel's centroid lies off a curved or grazed surface, and the two scans see it from different places: 0.1
  /// rather than 0.3 takes the mean rotation error from 0.034° to 0.024° on the simulated drives, at the same
  /// number of ICP points (BENCHMARKS.md, "Fine registration").
  double voxel = 0.1;
  /// Most query points kept after downsampling; beyond it an even stride over the voxels.
  int max_points = 8000;
  /// Voxel leaf (m) of the match (target) scan's stable-class points, whose planes the query points meet: finer,
  /// so a plane's normal and offset come from many points.
  double match_voxel = 0.2;
  /// Most match points kept. Online, every frame keeps its match cloud: at most 6 · this bytes (60 KB); twice
  /// as many were no more accurate (BENCHMARKS.md, "Fine registration").
  int match_max_points = 10000;
  /// Neighbours (the point included) whose covariance gives a target point's normal.
  int normal_neighbors = 10;
  /// A source point pairs with its nearest target point only if it lies this close (m), 3-D distance: pairs
  /// farther apart join different surfaces (docs/registration.md, "ICP"); the coarse stage brings the seed within
  /// reach.
  double max_correspondence = 0.3;
  /// Pairing distance (m) of a first, coarse ICP stage before the stage at max_correspondence; no coarse stage if
  /// not above max_correspondence. A seed from a few node centres can be a metre and some degrees off.
  double coarse_correspondence = 1.0;
  /// Scale k (m) of the Cauchy weight 1 / (1 + r²/k²) on point-to-plane residuals r; 0 = unweighted (a weight
  /// moved KITTI 00 4501 → 52 away from the ICP reference: docs/registration.md, "ICP").
  double kernel = 0.0;
  /// Gauss-Newton iterations at most.
  int max_iterations = 30;
  /// Converged once an update moves by less than this: translation in metres and rotation in radians. 0.1 mm and
  /// 0.006° lie far below the refined pose's error (0.4 cm / 0.024° on the simulated drives); a tighter bound only
  /// adds iterations (BENCHMARKS.md, "Fine registration").
  double convergence = 1e-4;
  /// Fitness = share of source points paired within max_correspondence at the final pose; below this the
  /// refinement fails and the SVD pose is kept.
  double min_fitness = 0.3;
  /// The refinement fails (SVD pose kept) if it moves the pose by more than this translation (m) ...
  /// A bound on divergence, not on the seed's error: a seed from 3–5 node centres of a 32-beam scan is often
  /// 0.5–2 m and 2–27° off, and the two ICP stages bring it within 0.3 m / 2° (BENCHMARKS.md, "Fine registration").
  double max_translation_change = 5.0;
  /// ... or by more than this rotation (degrees).
  double max_rotation_change_deg = 30.0;
  /// Floor of the point-to-plane residual σ (m) in the information matrix.
  double information_sigma_min = 0.01;
  /// Scales the information Σ JᵀJ / σ² down (< 1): neighbouring points share one surface and one scan, so they
  /// are not independent observations. Unitless.
  double information_scale = 0.01;
};

}  // namespace sgtllc
