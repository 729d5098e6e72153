#include "sgtllc/eval/report.h"

#include "sgtllc/eval/metric_text.h"

namespace sgtllc::eval {
namespace {

Json curveJson(const CurveMetrics& c) {
  return {{"positive_distance_m", c.positive_distance}, {"f1_max", metricJson(c.f1_max, c.defined())},
          {"ep", metricJson(c.ep, c.defined())},
          {"recall_at_100_precision", metricJson(c.recall_at_100_precision, c.defined())},
          {"n_positive", c.n_positive}, {"n_negative", c.n_negative}};
}

Json poseJson(const PoseSummary& p) {
  return {{"evaluated", p.evaluated}, {"successes", p.successes},
          {"success_rate", metricJson(p.success_rate, p.rateDefined())},
          {"rte_mean_m", metricJson(p.rte_mean, p.meansDefined())},
          {"rre_mean_deg", metricJson(p.rre_mean, p.meansDefined())}};
}

/// The top-1 curve with where the top-1 candidates lie.
Json top1Json(const SequenceMetrics& m) {
  Json j = curveJson(m.top1);
  j["near"] = m.top1_counts.near;
  j["lateral"] = m.top1_counts.lateral;
  j["far"] = m.top1_counts.far;
  j["no_candidate"] = m.top1_counts.none;
  return j;
}

/// The online refinement's statuses, time and store; null when registration.online was off.
Json refinementJson(const RefinementStats& r) {
  if (!r.enabled) return nullptr;
  Json by_status = Json::object();
  for (int k = 0; k < kRefinementStatuses; ++k) {
    by_status[refinementStatusName(static_cast<RefinementStatus>(k))] = r.by_status[static_cast<size_t>(k)];
  }
  return {{"refined", r.refined},
          {"used", r.used},
          {"fallbacks", r.fallbacks()},
          {"by_status", by_status},
          {"ms_per_frame_median", r.ms_per_frame_median},
          {"ms_per_frame_mean", r.ms_per_frame_mean},
          {"cloud_bytes_per_frame", r.cloud_bytes_per_frame}};
}

}  // namespace

Json sequenceMetricsJson(const SequenceMetrics& m) {
  const CurveMetrics& main = m.pairwise.at(0);
  Json distance_test = Json::array();
  for (const CurveMetrics& c : m.pairwise) distance_test.push_back(curveJson(c));
  const PoseSummary& p = m.poses;
  return {{"mode", "sequence"},
          {"f1_max", metricJson(main.f1_max, main.defined())},
          {"ep", metricJson(main.ep, main.defined())},
          {"recall_at_100_precision", metricJson(main.recall_at_100_precision, main.defined())},
          {"retrieval_recall_at_15", metricJson(m.retrieval_recall, m.n_revisit_queries > 0)},
          {"rte_mean", metricJson(p.rte_mean, p.meansDefined())},
          {"rre_mean", metricJson(p.rre_mean, p.meansDefined())},
          {"success_rate", metricJson(p.success_rate, p.rateDefined())},
          {"null_reasons", undefinedJson(undefinedMetrics(m))},
          {"n_frames", m.n_frames},
          {"n_queries", m.n_queries},
          {"n_revisit_queries", m.n_revisit_queries},
          {"n_positive", main.n_positive},
          {"n_negative", main.n_negative},
          {"ms_per_frame_median", m.ms_per_frame_median},
          {"ms_per_frame_p99", m.ms_per_frame_p99},
          {"db_bytes_per_frame", m.db_bytes_per_frame},
          {"loops",
           {{"detected", m.loops_detected},
            {"true", m.loops_true},
            {"false", m.loops_false},
            {"lateral", m.loops_lateral},
            {"reported_lateral", m.loops_reported_lateral},
            {"pose_correct", m.loops_pose_correct},
            {"false_pose_correct", m.loops_false_pose_correct}}},
          {"poses", poseJson(m.poses)},
          {"refinement", refinementJson(m.refinement)},
          {"top1", top1Json(m)},
          {"top1_no_lateral", curveJson(m.top1_no_lateral)},
          {"top1_score_only", curveJson(m.top1_score_only)},
          {"distance_test", distance_test}};
}

Json pairListMetricsJson(const PairListMetrics& m, const PairListRun& run, size_t list_limit) {
  const CurveMetrics& c = m.curve;
  const PoseSummary& p = m.poses;
  Json out = {{"mode", "pairs"},
              {"f1_max", metricJson(c.f1_max, c.defined())},
              {"ep", metricJson(c.ep, c.defined())},
              {"recall_at_100_precision", metricJson(c.recall_at_100_precision, c.defined())},
              {"n_pairs", m.n_pairs},
              {"n_available", m.n_available},
              {"n_positive", m.curve.n_positive},
              {"n_negative", m.curve.n_negative},
              {"correct", m.correct},
              {"positives_scored_zero", m.positives_scored_zero},
              {"rte_mean", metricJson(p.rte_mean, p.meansDefined())},
              {"rre_mean", metricJson(p.rre_mean, p.meansDefined())},
              {"success_rate", metricJson(p.success_rate, p.rateDefined())},
              {"null_reasons", undefinedJson(undefinedMetrics(m))},
              {"poses", poseJson(p)}};
  if (static_cast<size_t>(m.n_available) <= list_limit) {
    Json list = Json::array();
    for (const PairRecord& r : run.pairs) {
      if (!r.available) continue;
      Json item = {{"query", r.pair.query}, {"candidate", r.pair.candidate}, {"label", r.pair.loop ? 1 : 0},
                   {"loop", r.is_loop},     {"score", r.score},           {"score_t", r.score},
                   {"score_c", r.score_c},  {"rejection", rejectionName(r.rejection)}};
      if (r.pose_evaluated) {
        item["rte_m"] = r.pose_error.translation_m;
        item["rre_deg"] = r.pose_error.rotation_deg;
      }
      list.push_back(item);
    }
    out["pair_results"] = list;
  }
  return out;
}

}  // namespace sgtllc::eval
