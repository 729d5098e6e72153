/// @file report.h
/// @brief Evaluation output: the metrics as JSON, and a report folder (report.md, metrics.json, CSV tables and
///        PNG plots) a person reads at a glance.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "sgtllc/eval/pair_eval.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/output_file.h"

namespace sgtllc::eval {

using Json = nlohmann::ordered_json;

/// What the report says about where its numbers come from.
struct ReportInfo {
  std::string input;          ///< sequence or node folder
  std::string pairs_file;     ///< pair list, if any
  std::string command;        ///< the command line that produced it
  std::string config_yaml;    ///< the full configuration used
  std::string data_note;      ///< e.g. which data this is (real KITTI, simulated, ...)
  std::string software;       ///< e.g. "sgtllc 0.1.0, commit 0158456abcde" (a report line if not empty)
  /// When and where it ran: the only report.md lines that differ between two runs of the same command, apart
  /// from the measured times (each a report line if not empty).
  std::string date;
  std::string machine;
};

/// What a caller adds to a sequence report, e.g. the trajectory errors of `sgtllc eval --odometry`.
struct ReportExtra {
  std::string section;                ///< markdown placed after the summary
  Json metrics = Json::object();      ///< keys added to metrics.json
};

/// Sequence metrics with the keys `f1_max`, `ep`, `recall_at_100_precision`, `retrieval_recall_at_15`,
/// `rte_mean`, `rre_mean`, `success_rate`, `n_queries`, `n_positive`, `ms_per_frame_median`, `ms_per_frame_p99`,
/// `db_bytes_per_frame`, the distance test, `loops` (`detected`, `true`, `false`, `lateral` = 3–20 m, …), and the
/// top-1 protocol: `top1` (its curve's `f1_max`, `ep`, …, `n_positive`, `n_negative`, and where the top-1
/// candidates lie: `near` < 3 m, `lateral` 3–20 m, `far` > 20 m, `no_candidate`) and `top1_no_lateral` (the same
/// curve with the lateral top-1 left out) and `top1_score_only` (score alone, no lateral check); `loops` also
/// has `reported_lateral` (loops the detector itself reported as lateral).
Json sequenceMetricsJson(const SequenceMetrics& m);
/// Pair-list metrics (`f1_max`, `ep`, `recall_at_100_precision`, counts, pose summary) and, for lists of at most
/// @p list_limit pairs, every pair's result.
Json pairListMetricsJson(const PairListMetrics& m, const PairListRun& run, size_t list_limit = 100);

/// The pair-list protocol as a report.md section ("## Pair list"), for a sequence report that scores the folder's
/// loop_pairs.txt too (ReportExtra::section); @p note (if any) says which pairs were left out.
std::string pairListSection(const PairListMetrics& m, const std::string& file, const std::string& note);

/// Every file writeSequenceReport() writes into @p dir, report.md last.
std::vector<std::string> sequenceReportFiles(const std::string& dir);
/// Every file writePairListReport() writes into @p dir, report.md last.
std::vector<std::string> pairListReportFiles(const std::string& dir);

/// Writes report.md, metrics.json, pr_curve.csv, frames.csv, candidates.csv and pr_curves.png, timing.png,
/// memory.png, trajectory.png into @p dir (created if needed). Throws sgtllc::Error naming a file that cannot be
/// written. With Overwrite::kRefuse it checks that none of them exists before writing any, and each file's final
/// rename refuses one that appeared meanwhile (io/output_file.h).
void writeSequenceReport(const std::string& dir, const SequenceRun& run, const SequenceMetrics& m,
                         const EvalOptions& options, const ReportInfo& info, const ReportExtra& extra = {},
                         io::Overwrite overwrite = io::Overwrite::kReplace);
/// Writes report.md, metrics.json, pr_curve.csv, pairs.csv and pr_curves.png into @p dir, as writeSequenceReport().
void writePairListReport(const std::string& dir, const PairListRun& run, const PairListMetrics& m,
                         const ReportInfo& info, io::Overwrite overwrite = io::Overwrite::kReplace);

}  // namespace sgtllc::eval
