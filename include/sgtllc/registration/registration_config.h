/// @file registration_config.h
/// @brief Settings of the fine registration that refines a loop's object-level SVD pose (issue 13 item 4;
///        docs/registration.md).
#pragma once

namespace sgtllc {

/// Point-to-plane ICP on the stable-class points of both scans, seeded by the SVD pose of verification.
/// YAML keys `registration.NAME`; the range of each field is in brackets.
struct RegistrationConfig {
  /// Refine the pose of comparePair (`sgtllc pair`) when both inputs are labelled scans (node input has no points).
  bool pair = true;
  /// Refine the pose of the online detector's declared loop (the chosen candidate only). Keeps a compact cloud of
  /// every frame: at most match_max_points points of 6 bytes (int16 centimetres) per frame.
  bool online = false;
  /// Voxel leaf (m) of the query (source) scan's stable-class points: the points that are moved [0.05, 10].
  double voxel = 0.5;
  /// Most query points kept after downsampling; beyond it an even stride over the voxels [100, 1000000].
  int max_points = 4000;
  /// Voxel leaf (m) of the match (target) scan's stable-class points, whose planes the query points meet: finer,
  /// so a plane's normal and offset come from many points [0.05, 10].
  double match_voxel = 0.2;
  /// Most match points kept [100, 1000000]. Online, every frame keeps its match cloud: at most 6 · this bytes.
  int match_max_points = 20000;
  /// Neighbours (the point included) whose covariance gives a target point's normal [5, 100].
  int normal_neighbors = 10;
  /// A source point pairs with its nearest target point only if it lies this close (m), 3-D distance (0, 10].
  double max_correspondence = 1.0;
  /// Scale k (m) of the Cauchy weight 1 / (1 + r²/k²) on point-to-plane residuals r; 0 = unweighted [0, 10]. (On
  /// KITTI 00 4501 → 52, k = 0.1 m moved the result away from the ICP reference: 0.4 → 1.1 cm.)
  double kernel = 0.0;
  /// Gauss-Newton iterations at most [1, 500].
  int max_iterations = 30;
  /// Converged once an update moves by less than this: translation in metres and rotation in radians (0, 0.1].
  double convergence = 1e-5;
  /// Fitness = share of source points paired within max_correspondence at the final pose; below this the
  /// refinement fails and the SVD pose is kept [0, 1].
  double min_fitness = 0.3;
  /// The refinement fails (SVD pose kept) if it moves the pose by more than this translation (m) (0, 100] ...
  double max_translation_change = 0.5;
  /// ... or by more than this rotation (degrees) (0, 180].
  double max_rotation_change_deg = 2.0;
  /// Floor of the point-to-plane residual σ (m) in the information matrix (0, 10].
  double information_sigma_min = 0.01;
  /// Scales the information Σ JᵀJ / σ² down (< 1): neighbouring points share one surface and one scan, so they
  /// are not independent observations. Unitless (0, 1].
  double information_scale = 0.01;
};

}  // namespace sgtllc
