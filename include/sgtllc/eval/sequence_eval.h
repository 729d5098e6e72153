/// @file sequence_eval.h
/// @brief The paper's protocol over a whole sequence (algorithm §9): every query's 15 candidates scored against
///        ground truth, PR curves at several positive distances, the top-1 protocol, retrieval recall, pose
///        errors and per-frame cost.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/eval/ground_truth.h"
#include "sgtllc/eval/metrics.h"
#include "sgtllc/eval/refinement_stats.h"

namespace sgtllc::eval {

struct EvalOptions {
  /// Ground-truth distances (m) below which a pair is a true loop, one PR curve each; the first is the main one.
  std::vector<double> positive_distances = {3.0, 5.0, 10.0, 15.0};
  double negative_distance = 20.0;     ///< pairs farther apart are negatives; pairs in between are left out (m)
  double pose_max_distance = 4.0;      ///< detected loops this close get a pose error (SGLC's loop_distance4) (m)
  double success_translation = 2.0;    ///< a pose succeeds with RTE below this (m) ...
  double success_rotation = 5.0;       ///< ... and RRE below this (deg)
  int threads = 1;                     ///< reading and clustering threads (results do not depend on it)
  /// Called after every frame with (frames done, total, loops so far).
  std::function<void(size_t, size_t, int)> progress;
  /// Called after every frame with its index, the detector's result and the detector (its database holds the
  /// frame's nodes), e.g. to build loop edges for a pose graph.
  std::function<void(size_t, const FrameResult&, const LoopDetector&)> on_frame;
};

/// One retrieved candidate of a query, with its ground truth.
struct CandidateRecord {
  long frame = -1;             ///< frame number of the candidate
  double score = 0.0;        ///< final score (0 when a gate failed)
  double score_c = 0.0;
  double distance = 0.0;       ///< ground-truth distance to the query (m)
  double descriptor_distance2 = 0.0;  ///< squared L2 distance of the global descriptors
  Rejection rejection = Rejection::kFewAssociations;
  double estimated_distance = 0.0;  ///< ‖t(T_match_query)‖, the verified pose's offset (m); 0 unless verified
  bool retrieved = true;  ///< false: a neighbour of the top-1 (Candidate::retrieved), not in the pairwise protocol
  int associations = 0;   ///< |LA|, the associated node pairs before RANSAC (algorithm §7.1)
  int inliers = 0;        ///< verified node pairs (RANSAC's or guided matching's; algorithm §7.2)
  int match_nodes = 0;    ///< the candidate's node count (the overlap score divides by the larger graph)
  double footprint_share = -1.0;  ///< MatchResult::footprint share; −1 where the check did not run
  SeenThrough seen{};  ///< MatchResult::footprint's seen-through check (judged 0 where it did not run)
  bool by_consistency = false;    ///< MatchResult::by_consistency: verified by the consistency path (algorithm §7.8)
};

/// Everything measured for one frame.
struct FrameRecord {
  long frame = -1;            ///< frame number (poses.txt line)
  std::string name;
  int num_nodes = 0;
  bool queried = false;       ///< the database had eligible frames (past the exclusion gap and warm-up)
  bool has_revisit = false;   ///< an eligible frame lies within the main positive distance
  std::vector<CandidateRecord> candidates;  ///< ascending frame
  int best = -1;              ///< index into candidates of the highest score, or −1
  bool is_loop = false;       ///< the detector declared a loop with candidates[best]
  bool lateral = false;       ///< the detector reported candidates[best] as lateral (FrameResult::lateral)
  Eigen::Matrix4d T_match_query = Eigen::Matrix4d::Identity();  ///< the loop's pose (if is_loop)
  bool pose_evaluated = false;  ///< is_loop and within pose_max_distance: counts in the published pose table
  PoseError pose_error;         ///< the loop's pose against ground truth, at any distance (if is_loop)
  StageTimes timing;
  double load_ms = 0.0;
  size_t db_bytes = 0;        ///< database size after this frame
  /// How the online refinement of the loop's pose ended (registration.online); nullopt if it was not refined.
  std::optional<RefinementStatus> refinement;
};

struct SequenceRun {
  std::vector<FrameRecord> frames;
  std::vector<Eigen::Vector3d> positions;  ///< ground-truth LiDAR position of each frame
  bool contiguous = true;  ///< frame numbers are 0, 1, 2, …; otherwise the exclusion gap counts processed frames
  bool refinement_online = false;  ///< registration.online was on
  size_t cloud_bytes = 0;  ///< the detector's registration cloud store at the end (CloudStore::bytes)
};

/// Streams @p source through a LoopDetector(@p config) and records every query against @p truth. Throws
/// sgtllc::Error if a frame name is not a frame number with a ground-truth pose.
SequenceRun runSequenceEvaluation(const pipeline::FrameSource& source, const GroundTruth& truth, const Config& config,
                                  const EvalOptions& options);

/// Metrics of one PR curve.
struct CurveMetrics {
  double positive_distance = 0.0;
  PrCurve curve;
  double f1_max = 0.0;
  double ep = 0.0;
  double recall_at_100_precision = 0.0;
  int n_positive = 0;
  int n_negative = 0;
  /// F1max, EP and recall need positives (the recall denominator, curve.positives): without any they are
  /// undefined, reported as `n/a` / `null`, never as 0 (their fields then hold 0).
  bool defined() const { return curve.positives > 0; }
};

/// Where the queries' top-1 candidates lie (the top-1 protocol's samples, by ground-truth distance).
struct Top1Counts {
  int near = 0;     ///< top-1 closer than the main positive distance (3 m): a correct revisit
  int lateral = 0;  ///< top-1 between the positive and the negative distance (3–20 m): a neighbour, not the revisit
  int far = 0;      ///< top-1 beyond the negative distance (20 m): a wrong place
  int none = 0;     ///< queried frames without any candidate (no top-1)
};

struct SequenceMetrics {
  std::vector<CurveMetrics> pairwise;  ///< algorithm §9 pairwise protocol, one per positive distance ([0] is the main)
  /// One sample per query: its chosen candidate (FrameRecord::best) with its score, or score 0 if the detector
  /// reported it as lateral (its own pose puts it ≥ verification.lateral_distance away: not claimed as the
  /// revisit); if none passed the gates, its nearest global descriptor with score 0 (Scan Context / SSC
  /// protocol). A top-1 at or beyond the main positive distance is a false positive; recall counts against
  /// n_revisit_queries.
  CurveMetrics top1;
  /// The same with score for every chosen candidate, lateral or not (score alone, as peers without a pose).
  CurveMetrics top1_score_only;
  /// The same with the lateral top-1 samples (3–20 m) left out, as the pairwise protocol leaves out its 3–20 m
  /// pairs; the recall denominator is still n_revisit_queries.
  CurveMetrics top1_no_lateral;
  Top1Counts top1_counts;              ///< the top-1 samples by distance band
  int n_frames = 0;
  int n_queries = 0;                   ///< frames that were queried
  int n_revisit_queries = 0;           ///< queried frames with a true revisit (main positive distance)
  double retrieval_recall = 0.0;       ///< share of revisit queries with a true match among their candidates
                                       ///< (undefined, 0, without revisit queries)
  int loops_detected = 0;
  int loops_true = 0;                  ///< detected loops whose match is within the main positive distance
  int loops_false = 0;                 ///< detected loops whose match is beyond the negative distance
  int loops_lateral = 0;               ///< detected loops in between (3–20 m): neighbours of the revisit
  int loops_reported_lateral = 0;      ///< detected loops the detector itself reported as lateral (FrameRecord)
  /// Detected loops whose pose meets the success bounds, at any distance: a loop between overlapping views
  /// 20 m apart is a "false" loop by the distance protocol but a correct constraint for a pose graph.
  int loops_pose_correct = 0;
  int loops_false_pose_correct = 0;    ///< ... of them, false loops
  PoseSummary poses;
  double ms_per_frame_median = 0.0;    ///< extraction + description + retrieval + verification (reading excluded)
  double ms_per_frame_p99 = 0.0;
  double db_bytes_per_frame = 0.0;     ///< final database size / frames
  RefinementStats refinement;          ///< the online refinement's statuses, time and store (registration.online)
};

SequenceMetrics computeSequenceMetrics(const SequenceRun& run, const EvalOptions& options);

/// Metrics of a pooled sample set (shared by the sequence and pair-list protocols).
CurveMetrics curveMetrics(const std::vector<ScoredSample>& samples, double positive_distance,
                          int positives_override = 0);

/// The q-quantile (0..1) of @p values, nearest rank; 0 for none.
double percentile(std::vector<double> values, double q);

}  // namespace sgtllc::eval
