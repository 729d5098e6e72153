#include "sgtllc/eval/metrics.h"

#include <algorithm>
#include <cmath>

namespace sgtllc::eval {

PrCurve precisionRecallCurve(std::vector<ScoredSample> samples, int positives_override) {
  // Highest score first; equal scores form one threshold group.
  std::stable_sort(samples.begin(), samples.end(),
                   [](const ScoredSample& a, const ScoredSample& b) { return a.score > b.score; });
  PrCurve curve;
  int total_positive = 0;
  for (const ScoredSample& s : samples) total_positive += s.positive;
  curve.positives = positives_override > 0 ? positives_override : total_positive;
  int tp = 0, fp = 0;
  for (size_t k = 0; k < samples.size(); ++k) {
    samples[k].positive ? ++tp : ++fp;
    const bool group_end = k + 1 == samples.size() || samples[k + 1].score != samples[k].score;
    if (!group_end) continue;
    curve.thresholds.push_back(samples[k].score);
    curve.precision.push_back(static_cast<double>(tp) / (tp + fp));
    curve.recall.push_back(curve.positives > 0 ? static_cast<double>(tp) / curve.positives : 0.0);
  }
  curve.precision.push_back(1.0);
  curve.recall.push_back(0.0);
  return curve;
}

double f1Max(const PrCurve& curve) {
  if (curve.positives == 0) return 0.0;
  double best = 0.0;
  for (size_t k = 0; k < curve.precision.size(); ++k) {
    const double p = curve.precision[k], r = curve.recall[k];
    if (p + r > 0.0) best = std::max(best, 2.0 * p * r / (p + r));
  }
  return best;
}

double recallAt100Precision(const PrCurve& curve) {
  double best = 0.0;
  for (size_t k = 0; k < curve.precision.size(); ++k) {
    if (curve.precision[k] == 1.0) best = std::max(best, curve.recall[k]);
  }
  return best;
}

double extendedPrecision(const PrCurve& curve) {
  if (curve.positives == 0) return 0.0;
  // sklearn lists points by increasing threshold and numpy's argmin takes the first minimum: recall 0 at a real
  // threshold (the top-scored group holds no positive, precision 0) comes before the appended (1, 0) point.
  const bool top_group_has_positive = curve.recall.size() > 1 && curve.recall.front() > 0.0;
  const double precision_at_min_recall = top_group_has_positive ? 1.0 : 0.0;
  return 0.5 * (precision_at_min_recall + recallAt100Precision(curve));
}

PoseError poseError(const Eigen::Matrix4d& estimate, const Eigen::Matrix4d& ground_truth) {
  const Eigen::Matrix3d d = estimate.topLeftCorner<3, 3>().transpose() * ground_truth.topLeftCorner<3, 3>();
  const double c = std::clamp((d.trace() - 1.0) / 2.0, -1.0, 1.0);
  return {(ground_truth.topRightCorner<3, 1>() - estimate.topRightCorner<3, 1>()).norm(),
          std::acos(c) * 180.0 / M_PI};
}

PoseSummary summarisePoses(const std::vector<PoseError>& errors, double max_translation_m, double max_rotation_deg) {
  PoseSummary s;
  s.evaluated = static_cast<int>(errors.size());
  for (const PoseError& e : errors) {
    if (e.succeeds(max_translation_m, max_rotation_deg)) {
      ++s.successes;
      s.rte_mean += e.translation_m;
      s.rre_mean += e.rotation_deg;
    }
  }
  if (s.successes > 0) {
    s.rte_mean /= s.successes;
    s.rre_mean /= s.successes;
  }
  s.success_rate = s.evaluated > 0 ? static_cast<double>(s.successes) / s.evaluated : 0.0;
  return s;
}

}  // namespace sgtllc::eval
