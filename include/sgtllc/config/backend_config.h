/// @file backend_config.h
/// @brief Settings of the pose-graph back end (docs/backend.md): odometry noise, loop information, outlier step, solver.
///
/// YAML keys mirror the fields under `backend.` (`backend.odometry.translation_sigma_per_m`, …). The model behind
/// each group is described in docs/backend.md.
#pragma once

namespace sgtllc::backend {

/// Odometry information: a relative motion of d metres and θ radians has independent per-axis standard deviations
///   σ_t = sqrt(translation_sigma_min² + (translation_sigma_per_m · d)²)                          (m)
///   σ_r = sqrt(rotation_sigma_min² + (rotation_sigma_per_m · d)² + (rotation_sigma_per_rad · θ)²)  (rad)
/// and information diag(1/σ_t² ×3, 1/σ_r² ×3). Defaults fit LiDAR odometry such as KISS-ICP on KITTI (≈ 1 %
/// translation drift); only the ratio to the loop information shapes the solution.
struct OdometryNoise {
  double translation_sigma_per_m = 0.01;    ///< translation σ per metre travelled (m/m)
  double translation_sigma_min = 0.01;      ///< translation σ floor (m), for a standing vehicle
  double rotation_sigma_per_m = 2.0e-4;     ///< rotation σ per metre travelled (rad/m)
  double rotation_sigma_per_rad = 0.01;     ///< rotation σ per radian turned (rad/rad)
  double rotation_sigma_min = 2.0e-4;       ///< rotation σ floor (rad)
};

/// Loop information from the object-level fit (see loopInformation): point-to-point Gauss-Newton information of
/// the inlier node centres with an isotropic per-axis noise σ = max(sigma_min, residual estimate).
struct LoopNoise {
  double sigma_min = 0.15;  ///< floor of the per-axis centre noise σ (m); node centres move with segmentation
  /// Scales the fit's information down (< 1) to account for errors shared by all centres of a frame (one
  /// segmentation, one scan), which the independent-noise model ignores. Unitless.
  double information_scale = 0.25;
};

/// Robust loss on loop edges (over the whitened residual norm s = sqrt(eᵀΩe)).
enum class RobustLoss {
  kNone,    ///< plain least squares
  kHuber,   ///< quadratic below `loss_scale`, linear above
  kCauchy,  ///< ρ(s²) = a² log(1 + s²/a²), a = `loss_scale`: down-weights gross errors strongly [default]
};

/// Pairwise consistency of two loops (a→b) and (c→d) with the odometry (the outlier step, after PCM): the cycle
/// a →(odometry) c →(loop) d →(odometry) b →(loop⁻¹) a must close within
///   translation:  translation_m + translation_per_m · L   (m)
///   rotation:     rotation_rad + rotation_per_m · L        (rad)
/// with L the odometry path length of the two legs a–c and d–b (m). The bound grows with L because the odometry
/// drifts; the loops kept are a maximum set of mutually consistent ones (greedy maximum clique, deterministic).
struct LoopConsistency {
  double translation_m = 1.5;         ///< cycle translation bound at L = 0 (m): twice a loop's pose error
  double translation_per_m = 0.02;    ///< growth with odometry path length (m/m): a few times the drift
  double rotation_rad = 0.1;          ///< cycle rotation bound at L = 0 (rad, ≈ 5.7°)
  double rotation_per_m = 2.0e-4;     ///< growth with odometry path length (rad/m)
};

struct SolverSettings {
  int num_threads = 1;            ///< Ceres threads (Jacobian evaluation, linear algebra); output is the same for any
  int max_iterations = 100;       ///< trust-region (Dogleg) iterations per solve
  double function_tolerance = 1e-10;  ///< stop when the relative cost change falls below this
  double parameter_tolerance = 1e-10; ///< stop when the relative step falls below this
  /// optimize() first solves the reduced graph (see OnlineSettings) from the current estimate and starts the full
  /// solve from its result: fewer full iterations to the same optimum (the full solve has the last word).
  bool reduced_warm_start = true;
};

/// How PoseGraphOptimizer::closeLoop re-optimises when a loop arrives (docs/backend.md, "Online").
struct OnlineSettings {
  /// true: optimise the reduced graph, whose poses are only the anchors (frame 0, the loop endpoints, one per
  /// stretch of path, the newest frame) joined by the composed odometry between them, then place the frames in
  /// between from the two anchors (first order); milliseconds on KITTI 00. optimize() still solves the full graph,
  /// and its result is the batch result. false: every closeLoop solves the full graph.
  bool reduced_graph = true;
  /// Stretch of odometry path (m) whose loop endpoints share one anchor of the reduced graph, the middle one; a
  /// loop ending elsewhere is carried along the odometry to the nearer anchor, so the anchors stay under the path
  /// length over the spacing however many loops arrive (docs/backend.md, "Online"). 0: every loop endpoint is an
  /// anchor.
  double anchor_spacing_m = 5.0;
};

/// How a new session joins a saved map (docs/sessions.md).
struct SessionSettings {
  /// Inter-session loops that must agree (the largest pairwise-consistent set) before a session is tied to the map;
  /// with fewer it stays in its own odometry frame and is not merged. Two, so that one wrong loop alone never places
  /// a session.
  int min_inter_loops = 2;
  /// A session frame joins the merged map unless the map recognised it (its inter-session loop was accepted) and a
  /// map frame lies within this distance (m) and keep_heading_deg of its pose: the map then grows with the streets
  /// covered, not with the drives (docs/sessions.md, "A map that does not grow with revisits"). 0: every frame joins.
  double keep_distance_m = 3.0;
  /// ... and heading: a map frame facing more than this away (deg) does not cover the session frame.
  double keep_heading_deg = 45.0;
  /// A covered frame the map did not recognise joins only while the map frames covering it come from fewer than
  /// this many sessions: a place the detector misses gains one more drive's view, not one per drive, so the map's
  /// size stays bounded by the streets (docs/sessions.md, "A map that does not grow with revisits"). 1: no
  /// unrecognised covered frame joins.
  int max_covering_sessions = 2;
};

struct BackendConfig {
  OdometryNoise odometry;
  LoopNoise loops;
  RobustLoss loop_loss = RobustLoss::kCauchy;  ///< robust loss on loop edges (odometry edges: plain squares)
  double loss_scale = 3.0;                     ///< a of the loss, in whitened units (σ); > 0
  LoopConsistency consistency;
  /// Residual check after optimising: a kept loop whose χ² = eᵀΩe exceeds this is rejected and the graph is
  /// re-optimised, worst first, one loop per round. 6 DoF; default ≈ the 0.999 quantile ×5 for model error.
  double max_loop_chi2 = 100.0;
  int max_rejection_rounds = 10;  ///< residual-check rounds (each re-optimises); the rest stays as it is
  SolverSettings solver;
  OnlineSettings online;
  SessionSettings sessions;

  /// Throws sgtllc::Error naming the offending key (`backend.…`) if a value is out of range.
  void validate() const;
};

}  // namespace sgtllc::backend
