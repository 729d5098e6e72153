#include "sgtllc/eval/report.h"

namespace sgtllc::eval {
namespace {

Json curveJson(const CurveMetrics& c) {
  return {{"positive_distance_m", c.positive_distance}, {"f1_max", c.f1_max}, {"ep", c.ep},
          {"recall_at_100_precision", c.recall_at_100_precision}, {"n_positive", c.n_positive},
          {"n_negative", c.n_negative}};
}

Json poseJson(const PoseSummary& p) {
  return {{"evaluated", p.evaluated}, {"successes", p.successes}, {"success_rate", p.success_rate},
          {"rte_mean_m", p.rte_mean}, {"rre_mean_deg", p.rre_mean}};
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

}  // namespace

Json sequenceMetricsJson(const SequenceMetrics& m) {
  const CurveMetrics& main = m.pairwise.at(0);
  Json distance_test = Json::array();
  for (const CurveMetrics& c : m.pairwise) distance_test.push_back(curveJson(c));
  return {{"mode", "sequence"},
          {"f1_max", main.f1_max},
          {"ep", main.ep},
          {"recall_at_100_precision", main.recall_at_100_precision},
          {"retrieval_recall_at_15", m.retrieval_recall},
          {"rte_mean", m.poses.rte_mean},
          {"rre_mean", m.poses.rre_mean},
          {"success_rate", m.poses.success_rate},
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
          {"top1", top1Json(m)},
          {"top1_no_lateral", curveJson(m.top1_no_lateral)},
          {"top1_score_only", curveJson(m.top1_score_only)},
          {"distance_test", distance_test}};
}

Json pairListMetricsJson(const PairListMetrics& m, const PairListRun& run, size_t list_limit) {
  Json out = {{"mode", "pairs"},
              {"f1_max", m.curve.f1_max},
              {"ep", m.curve.ep},
              {"recall_at_100_precision", m.curve.recall_at_100_precision},
              {"n_pairs", m.n_pairs},
              {"n_available", m.n_available},
              {"n_positive", m.curve.n_positive},
              {"n_negative", m.curve.n_negative},
              {"correct", m.correct},
              {"positives_scored_zero", m.positives_scored_zero},
              {"rte_mean", m.poses.rte_mean},
              {"rre_mean", m.poses.rre_mean},
              {"success_rate", m.poses.success_rate},
              {"poses", poseJson(m.poses)}};
  if (static_cast<size_t>(m.n_available) <= list_limit) {
    Json list = Json::array();
    for (const PairRecord& r : run.pairs) {
      if (!r.available) continue;
      Json p = {{"query", r.pair.query}, {"candidate", r.pair.candidate}, {"label", r.pair.loop ? 1 : 0},
                {"loop", r.is_loop},     {"score", r.score_t},           {"score_c", r.score_c},
                {"rejection", rejectionName(r.rejection)}};
      if (r.pose_evaluated) {
        p["rte_m"] = r.pose_error.translation_m;
        p["rre_deg"] = r.pose_error.rotation_deg;
      }
      list.push_back(p);
    }
    out["pair_results"] = list;
  }
  return out;
}

}  // namespace sgtllc::eval
