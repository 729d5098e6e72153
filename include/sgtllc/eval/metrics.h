/// @file metrics.h
/// @brief Loop-closure metrics: precision–recall curve, F1max, EP, recall at 100 % precision, pose errors
///        (algorithm §9).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace sgtllc::eval {

/// One scored sample: a (query, candidate) pair, or a query's top-1 prediction.
struct ScoredSample {
  double score = 0.0;     ///< the method's confidence (the loop score; 0 when a gate failed)
  bool positive = false;  ///< ground truth: a true loop
};

/// A precision–recall curve with one point per distinct score threshold, highest threshold first, as
/// sklearn.metrics.precision_recall_curve: a sample is predicted positive iff its score ≥ the threshold. The
/// point (precision 1, recall 0) is appended last, as sklearn does.
struct PrCurve {
  std::vector<double> thresholds;  ///< descending; one fewer than precision/recall (the appended point has none)
  std::vector<double> precision;
  std::vector<double> recall;
  int positives = 0;  ///< positives counted for recall (the denominator)
};

/// PR curve over pooled samples. @p positives_override > 0 replaces the recall denominator (top-1 protocol:
/// the number of queries that have a true revisit, whether or not their prediction is correct).
PrCurve precisionRecallCurve(std::vector<ScoredSample> samples, int positives_override = 0);

/// max 2PR / (P + R) over the curve; 0 where P + R = 0, and 0 without positives.
double f1Max(const PrCurve& curve);

/// Largest recall reached at precision exactly 1 (0 if none; the appended point guarantees ≥ 0).
double recallAt100Precision(const PrCurve& curve);

/// Extended precision EP = ½ (P_Rmin + R_P100) (algorithm §9): P_Rmin is the precision at the first point of minimal
/// recall — 1 if the top-scored group holds a positive, else 0.
double extendedPrecision(const PrCurve& curve);

/// Relative pose error of an estimate against the ground truth.
struct PoseError {
  double translation_m = 0.0;  ///< RTE = ‖t_gt − t_est‖
  double rotation_deg = 0.0;   ///< RRE = arccos((tr(R_estᵀ R_gt) − 1) / 2), clipped to [−1, 1]

  /// A success as published tables count it: RTE below @p max_translation_m and RRE below @p max_rotation_deg.
  bool succeeds(double max_translation_m, double max_rotation_deg) const {
    return translation_m < max_translation_m && rotation_deg < max_rotation_deg;
  }
};

PoseError poseError(const Eigen::Matrix4d& estimate, const Eigen::Matrix4d& ground_truth);

/// Success rate and mean errors over successes (RTE < max_translation and RRE < max_rotation), as published
/// tables report them.
struct PoseSummary {
  int evaluated = 0;            ///< loops with a pose compared
  int successes = 0;
  double success_rate = 0.0;    ///< successes / evaluated (0 if none)
  double rte_mean = 0.0;        ///< mean RTE over successes (m)
  double rre_mean = 0.0;        ///< mean RRE over successes (deg)
  /// The rate needs an evaluated pose and the means a success; otherwise they are undefined (reported as
  /// `n/a` / `null`; the fields hold 0).
  bool rateDefined() const { return evaluated > 0; }
  bool meansDefined() const { return successes > 0; }
};

PoseSummary summarisePoses(const std::vector<PoseError>& errors, double max_translation_m = 2.0,
                           double max_rotation_deg = 5.0);

}  // namespace sgtllc::eval
