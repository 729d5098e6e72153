#include "sgtllc/eval/sequence_eval.h"

#include <algorithm>

#include "sgtllc/io/quote.h"

namespace sgtllc::eval {

SequenceRun runSequenceEvaluation(const pipeline::FrameSource& source, const GroundTruth& truth, const Config& config,
                                  const EvalOptions& options) {
  SequenceRun run;
  std::vector<long> numbers(source.size());
  for (size_t i = 0; i < source.size(); ++i) {
    numbers[i] = source.number(i);
    if (!truth.has(numbers[i])) {
      throw Error("frame " + io::quoteContent(source.name(i)) + " has no ground-truth pose (poses.txt has " +
                  std::to_string(truth.size()) + " lines; frames must be named by their line number)");
    }
    run.positions.push_back(truth.pose(numbers[i]).topRightCorner<3, 1>());
    run.contiguous = run.contiguous && numbers[i] == static_cast<long>(i);
  }
  const double positive = options.positive_distances.at(0);
  const int gap = config.retrieval.exclude_recent;
  LoopDetector detector(config);
  int loops = 0;
  pipeline::streamSequence(source, detector, options.threads, [&](size_t i, const pipeline::LoadedFrame& loaded, const FrameResult& r) {
    FrameRecord rec;
    rec.frame = numbers[i];
    rec.name = source.name(i);
    rec.num_nodes = r.num_nodes;
    rec.timing = r.timing;
    rec.load_ms = loaded.load_ms;
    rec.db_bytes = detector.database().totalBytes() + detector.footprintBytes();
    rec.queried = static_cast<int>(i) >= config.retrieval.warmup_frames && static_cast<long>(i) - gap >= 0;
    if (rec.queried) {
      for (long j = 0; j <= static_cast<long>(i) - gap && !rec.has_revisit; ++j) {
        rec.has_revisit = truth.distance(numbers[i], numbers[j]) < positive;
      }
    }
    for (const Candidate& c : r.candidates) {
      const long f = numbers[static_cast<size_t>(c.frame)];
      rec.candidates.push_back(CandidateRecord{f, c.match.score, c.match.score_c, truth.distance(rec.frame, f),
                                               c.distance2, c.match.rejection,
                                               c.match.T_match_query.topRightCorner<3, 1>().norm(), c.retrieved});
      CandidateRecord& added = rec.candidates.back();
      for (const NodeMatch& a : c.match.associations) added.associations += a.guided ? 0 : 1;
      added.inliers = static_cast<int>(c.match.inliers.size());
      added.match_nodes = static_cast<int>(detector.database().nodes(c.frame).size());
      added.footprint_share = c.match.footprint.compared > 0 ? c.match.footprint.share : -1.0;
      added.seen = c.match.footprint.seen;
      added.by_consistency = c.match.by_consistency;
    }
    rec.best = r.best;
    rec.is_loop = r.is_loop;
    rec.lateral = r.lateral;
    if (const Candidate* loop = r.loop()) {
      ++loops;
      rec.T_match_query = loop->match.T_match_query;
      const long m = numbers[static_cast<size_t>(loop->frame)];
      rec.pose_error = poseError(rec.T_match_query, truth.relative(m, rec.frame));
      rec.pose_evaluated = truth.distance(rec.frame, m) <= options.pose_max_distance;
      if (loop->refinement) rec.refinement = loop->refinement->status;
    }
    run.frames.push_back(std::move(rec));
    if (options.on_frame) options.on_frame(i, r, detector);
    if (options.progress) options.progress(i + 1, source.size(), loops);
  });
  run.refinement_online = config.registration.online;
  run.cloud_bytes = detector.clouds().bytes();
  return run;
}

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t k = static_cast<size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(k, values.size() - 1)];
}

CurveMetrics curveMetrics(const std::vector<ScoredSample>& samples, double positive_distance, int positives_override) {
  CurveMetrics m;
  m.positive_distance = positive_distance;
  for (const ScoredSample& s : samples) (s.positive ? m.n_positive : m.n_negative)++;
  m.curve = precisionRecallCurve(samples, positives_override);
  m.f1_max = f1Max(m.curve);
  m.ep = extendedPrecision(m.curve);
  m.recall_at_100_precision = recallAt100Precision(m.curve);
  return m;
}

SequenceMetrics computeSequenceMetrics(const SequenceRun& run, const EvalOptions& options) {
  SequenceMetrics out;
  out.n_frames = static_cast<int>(run.frames.size());
  const double positive = options.positive_distances.at(0);
  // Pairwise protocol: every (query, candidate) pair is a sample; pairs between the positive and the negative
  // distance are left out (algorithm §9).
  for (double d : options.positive_distances) {
    std::vector<ScoredSample> samples;
    for (const FrameRecord& f : run.frames) {
      for (const CandidateRecord& c : f.candidates) {
        if (!c.retrieved) continue;  // the K retrieved per query, as the paper
        if (c.distance < d) samples.push_back({c.score, true});
        else if (c.distance > options.negative_distance) samples.push_back({c.score, false});
      }
    }
    out.pairwise.push_back(curveMetrics(samples, d));
  }

  // Top-1 protocol: each query's chosen candidate (or, if none passed the gates, its nearest global descriptor)
  // with its score; recall counts against all queries that have a true revisit. A wrong top-1 is a false positive
  // whatever its distance; the second curve leaves out the lateral ones (3–20 m), as the pairwise protocol does.
  std::vector<ScoredSample> top1, top1_no_lateral, top1_score_only;
  std::vector<double> frame_ms;
  for (const FrameRecord& f : run.frames) {
    frame_ms.push_back(f.timing.total_ms());
    if (!f.queried) continue;
    ++out.n_queries;
    out.n_revisit_queries += f.has_revisit;
    bool retrieved = false;
    for (const CandidateRecord& c : f.candidates) retrieved = retrieved || (c.retrieved && c.distance < positive);
    out.retrieval_recall += f.has_revisit && retrieved;
    if (f.candidates.empty()) {
      ++out.top1_counts.none;
    } else {
      // Neighbours are added only beside a chosen top-1, so without one every candidate was retrieved.
      const auto nearest = std::min_element(f.candidates.begin(), f.candidates.end(), [](const auto& a, const auto& b) {
        return a.descriptor_distance2 < b.descriptor_distance2;
      });
      const CandidateRecord& c = f.best >= 0 ? f.candidates[static_cast<size_t>(f.best)] : *nearest;
      const ScoredSample sample{f.best >= 0 && !f.lateral ? c.score : 0.0, c.distance < positive};
      top1.push_back(sample);
      top1_score_only.push_back({f.best >= 0 ? c.score : 0.0, sample.positive});
      const bool lateral = !sample.positive && c.distance <= options.negative_distance;
      if (!lateral) top1_no_lateral.push_back(sample);
      ++(sample.positive ? out.top1_counts.near : lateral ? out.top1_counts.lateral : out.top1_counts.far);
    }
    if (f.is_loop) {
      ++out.loops_detected;
      const double d = f.candidates[static_cast<size_t>(f.best)].distance;
      out.loops_true += d < positive;
      out.loops_false += d > options.negative_distance;
      out.loops_lateral += d >= positive && d <= options.negative_distance;
      out.loops_reported_lateral += f.lateral;
      const bool pose_ok = f.pose_error.succeeds(options.success_translation, options.success_rotation);
      out.loops_pose_correct += pose_ok;
      out.loops_false_pose_correct += pose_ok && d > options.negative_distance;
    }
  }
  out.retrieval_recall = out.n_revisit_queries > 0 ? out.retrieval_recall / out.n_revisit_queries : 0.0;
  out.top1 = curveMetrics(top1, positive, out.n_revisit_queries);
  out.top1_no_lateral = curveMetrics(top1_no_lateral, positive, out.n_revisit_queries);
  out.top1_score_only = curveMetrics(top1_score_only, positive, out.n_revisit_queries);

  std::vector<PoseError> errors;
  for (const FrameRecord& f : run.frames) {
    if (f.pose_evaluated) errors.push_back(f.pose_error);
  }
  out.poses = summarisePoses(errors, options.success_translation, options.success_rotation);
  out.ms_per_frame_median = percentile(frame_ms, 0.5);
  out.ms_per_frame_p99 = percentile(frame_ms, 0.99);
  std::vector<std::optional<RefinementStatus>> statuses;
  std::vector<double> refinement_ms;
  for (const FrameRecord& f : run.frames) {
    statuses.push_back(f.refinement);
    refinement_ms.push_back(f.timing.refinement_ms);
  }
  out.refinement = refinementStats(run.refinement_online, statuses, refinement_ms, run.cloud_bytes);
  out.db_bytes_per_frame = run.frames.empty() ? 0.0
                                              : static_cast<double>(run.frames.back().db_bytes) / run.frames.size();
  return out;
}

}  // namespace sgtllc::eval
