#include "sgtllc/eval/report.h"

#include <filesystem>
#include <map>
#include <sstream>

#include "report_plots.h"
#include "timing_plot.h"
#include "sgtllc/eval/metric_text.h"
#include "sgtllc/io/csv.h"

namespace fs = std::filesystem;

namespace sgtllc::eval {
namespace {

constexpr const char* kSequenceFiles[] = {"metrics.json", "pr_curve.csv",  "frames.csv", "candidates.csv",
                                           "pr_curves.png", "timing.png",    "memory.png", "trajectory.png",
                                           "report.md"};
constexpr const char* kPairListFiles[] = {"metrics.json", "pr_curve.csv", "pairs.csv", "pr_curves.png", "report.md"};

template <size_t N>
std::vector<std::string> inFolder(const std::string& dir, const char* const (&names)[N]) {
  std::vector<std::string> paths;
  for (const char* name : names) paths.push_back((fs::path(dir) / name).string());
  return paths;
}

/// Checks every file first (nothing is written if one of them may not be), then creates the folder.
fs::path prepare(const std::string& dir, const std::vector<std::string>& files, io::Overwrite overwrite) {
  if (fs::exists(dir) && !fs::is_directory(dir)) throw Error("cannot write report: " + dir + " is not a folder");
  io::checkOutputFiles(files, overwrite, true);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) throw Error("cannot create report folder " + dir + ": " + ec.message());
  return fs::path(dir);
}

/// The report's writers, bound to its folder and overwrite rule.
struct ReportWriter {
  fs::path dir;
  io::Overwrite overwrite;
  void text(const char* name, const std::string& content) const {
    io::writeFileAtomically((dir / name).string(), content, overwrite);
  }
  template <typename Plot>
  void png(const char* name, Plot&& plot) const {
    io::writeThroughTemporary((dir / name).string(), overwrite, plot);
  }
};

std::string prCsv(const std::vector<std::pair<std::string, const CurveMetrics*>>& curves) {
  std::ostringstream s;
  s << "curve,positive_distance_m,threshold,precision,recall\n";
  for (const auto& [name, c] : curves) {
    for (size_t k = 0; k < c->curve.precision.size(); ++k) {
      s << io::csvField(name) << "," << c->positive_distance << ",";
      if (k < c->curve.thresholds.size()) s << c->curve.thresholds[k];
      s << "," << c->curve.precision[k] << "," << c->curve.recall[k] << "\n";
    }
  }
  return s.str();
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << v;
  return s.str();
}

std::string provenance(const ReportInfo& info) {
  std::ostringstream s;
  s << "Input: `" << info.input << "`";
  if (!info.pairs_file.empty()) s << ", pair list `" << info.pairs_file << "`";
  s << ".\n\n";
  if (!info.data_note.empty()) s << info.data_note << "\n\n";
  if (!info.command.empty()) s << "Command:\n\n```sh\n" << info.command << "\n```\n\n";
  // One list item per line, so that a comparison of two reports can leave out the date and machine lines.
  if (!info.software.empty()) s << "- Software: " << info.software << "\n";
  if (!info.date.empty()) s << "- Date: " << info.date << "\n";
  if (!info.machine.empty()) s << "- Machine: " << info.machine << "\n";
  if (!info.software.empty() || !info.date.empty() || !info.machine.empty()) s << "\n";
  return s.str();
}

std::string configSection(const ReportInfo& info) {
  return info.config_yaml.empty() ? "" : "## Configuration\n\n```yaml\n" + info.config_yaml + "```\n";
}

/// The pose success rate's value and the mean errors' row.
std::string poseRows(const PoseSummary& p) {
  const std::string means = p.meansDefined() ? fixed(p.rte_mean, 3) + " m / " + fixed(p.rre_mean, 3) + "°" : "n/a";
  return " | " + metricText(p.success_rate, p.rateDefined(), 4) + " (" + std::to_string(p.successes) + " of " +
         std::to_string(p.evaluated) + ") |\n| RTE / RRE, mean over successes | " + means + " |\n";
}

/// The undefined metrics as a paragraph after a table, or "".
std::string undefinedParagraph(const std::vector<UndefinedMetrics>& list) {
  return list.empty() ? "" : "\n" + undefinedText(list, "- ");
}

std::string pairListTable(const PairListMetrics& m) {
  const CurveMetrics& c = m.curve;
  std::ostringstream md;
  md << "| metric | value |\n|---|---|\n| pairs listed / scored | " << m.n_pairs << " / " << m.n_available
     << " (the others name frames that are not in the input) |\n| positives / negatives scored | "
     << c.n_positive << " / " << c.n_negative << " |\n| positives scored 0 (rejected by a gate or "
     << "RANSAC) | " << m.positives_scored_zero << " |\n| decisions equal to the label | " << m.correct << " of "
     << m.n_available << " |\n| F1max | " << metricText(c.f1_max, c.defined(), 4) << " |\n| EP | "
     << metricText(c.ep, c.defined(), 4) << " |\n| recall at 100 % precision | "
     << metricText(c.recall_at_100_precision, c.defined(), 4) << " |\n| pose success rate" << poseRows(m.poses)
     << undefinedParagraph(undefinedMetrics(m));
  return md.str();
}

/// "F1MAX / EP" of a curve, n/a without positives.
std::string f1Ep(const CurveMetrics& c) {
  return metricText(c.f1_max, c.defined(), 4) + " / " + metricText(c.ep, c.defined(), 4);
}

/// The top-1 protocol with its distance bands.
std::string top1Section(const SequenceMetrics& m, const EvalOptions& options) {
  const std::string pos = fixed(options.positive_distances.at(0), 0), neg = fixed(options.negative_distance, 0);
  const Top1Counts& c = m.top1_counts;
  std::ostringstream md;
  md << "## Top-1 per query\n\nEach query's chosen candidate (its nearest global descriptor, score 0, if none "
        "passed verification); recall counts against the "
     << m.n_revisit_queries << " queries with a revisit < " << pos << " m.\n\n| top-1 | value |\n|---|---|\n"
     << "| top-1 < " << pos << " m / " << pos << "–" << neg << " m (lateral) / > " << neg << " m / no candidate | "
     << c.near << " / " << c.lateral << " / " << c.far << " / " << c.none << " |\n"
     << "| F1max / EP, a top-1 ≥ " << pos << " m counted false | " << f1Ep(m.top1)
     << " |\n| F1max / EP, lateral top-1 left out | " << f1Ep(m.top1_no_lateral)
     << " |\n| F1max / EP, score alone (no lateral check) | " << f1Ep(m.top1_score_only) << " |\n\n"
     << "A top-1 the detector reports as lateral (its pose puts it ≥ verification.lateral_distance away) is not "
        "claimed as a revisit: score 0 in the first two rows.\n\n";
  return md.str();
}

}  // namespace

std::string pairListSection(const PairListMetrics& m, const std::string& file, const std::string& note) {
  return "## Pair list\n\nEvery `query candidate label` pair of `" + file +
         "` scored on the frames of this run (the label as given).\n\n" + (note.empty() ? "" : note + "\n\n") +
         pairListTable(m) + "\n";
}

std::vector<std::string> sequenceReportFiles(const std::string& dir) { return inFolder(dir, kSequenceFiles); }
std::vector<std::string> pairListReportFiles(const std::string& dir) { return inFolder(dir, kPairListFiles); }

void writeSequenceReport(const std::string& dir, const SequenceRun& run, const SequenceMetrics& m,
                         const EvalOptions& options, const ReportInfo& info, const ReportExtra& extra,
                         io::Overwrite overwrite) {
  const ReportWriter out{prepare(dir, sequenceReportFiles(dir), overwrite), overwrite};
  Json metrics = sequenceMetricsJson(m);
  for (const auto& [key, value] : extra.metrics.items()) metrics[key] = value;
  out.text("metrics.json", metrics.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
  std::vector<std::pair<std::string, const CurveMetrics*>> curves;
  for (const CurveMetrics& c : m.pairwise) curves.emplace_back("pairwise", &c);
  curves.emplace_back("top1", &m.top1);
  curves.emplace_back("top1_no_lateral", &m.top1_no_lateral);
  curves.emplace_back("top1_score_only", &m.top1_score_only);
  out.text("pr_curve.csv", prCsv(curves));

  // Every frame column holds the frame's name (its file stem, e.g. 000395), as the `frame` column always did, as
  // a CSV field (csv.h: a file name may hold a comma).
  std::map<long, std::string> names;
  for (const FrameRecord& f : run.frames) names.emplace(f.frame, io::csvField(f.name));
  const auto name = [&names](long frame) {
    const auto it = names.find(frame);
    return it != names.end() ? it->second : std::to_string(frame);
  };
  std::ostringstream frames;
  frames << "frame,nodes,queried,has_revisit,loop,match,score,match_distance_m,extraction_ms,description_ms,"
            "retrieval_ms,verification_ms,db_bytes,loop_rte_m,loop_rre_deg\n";
  for (const FrameRecord& f : run.frames) {
    const CandidateRecord* best = f.best >= 0 ? &f.candidates[static_cast<size_t>(f.best)] : nullptr;
    frames << io::csvField(f.name) << "," << f.num_nodes << "," << f.queried << "," << f.has_revisit << "," << f.is_loop << ","
           << (best ? name(best->frame) : "") << "," << (best ? best->score : 0.0) << ","
           << (best ? best->distance : 0.0) << "," << f.timing.extraction_ms << "," << f.timing.description_ms << ","
           << f.timing.retrieval_ms << "," << f.timing.verification_ms << "," << f.db_bytes << ",";
    if (f.is_loop) frames << f.pose_error.translation_m << "," << f.pose_error.rotation_deg;
    else frames << ",";
    frames << "\n";
  }
  out.text("frames.csv", frames.str());

  std::ostringstream pairs;
  pairs << "query,candidate,distance_m,score,score_c,rejection,estimated_distance_m,retrieved,associations,inliers,"
           "query_nodes,candidate_nodes,footprint_share,path,seen_through_share,sight_judged\n";
  for (const FrameRecord& f : run.frames) {
    for (const CandidateRecord& c : f.candidates) {
      pairs << io::csvField(f.name) << "," << name(c.frame) << "," << c.distance << "," << c.score << "," << c.score_c << ","
            << rejectionName(c.rejection) << "," << c.estimated_distance << "," << (c.retrieved ? 1 : 0) << ","
            << c.associations << "," << c.inliers << "," << f.num_nodes << "," << c.match_nodes << ","
            << c.footprint_share << "," << (c.by_consistency ? "consistency" : "descriptors") << ","
            << (c.seen.judged > 0 ? c.seen.share() : -1.0) << "," << c.seen.judged << "\n";
    }
  }
  out.text("candidates.csv", pairs.str());

  out.png("pr_curves.png", [&](const std::string& tmp) {
    plotPrCurves(tmp, m.pairwise, &m.top1, "Precision-recall (pairwise protocol, top-15)");
  });
  out.png("timing.png", [&](const std::string& tmp) { plotTiming(tmp, run); });
  out.png("memory.png", [&](const std::string& tmp) { plotMemory(tmp, run); });
  out.png("trajectory.png", [&](const std::string& tmp) { plotTrajectory(tmp, run, options); });

  const CurveMetrics& main = m.pairwise.at(0);
  std::ostringstream md;
  md << "# Loop-closure evaluation\n\n" << provenance(info);
  md << "## Summary\n\n| metric | value |\n|---|---|\n"
     << "| F1max (pairwise, positive < " << fixed(main.positive_distance, 0) << " m) | "
     << metricText(main.f1_max, main.defined(), 4) << " |\n| EP | " << metricText(main.ep, main.defined(), 4)
     << " |\n| recall at 100 % precision | " << metricText(main.recall_at_100_precision, main.defined(), 4)
     << " |\n| F1max / EP, top-1 per query | " << f1Ep(m.top1) << " |\n| retrieval recall at 15 | "
     << metricText(m.retrieval_recall, m.n_revisit_queries > 0, 4)
     << " |\n| frames / queries / queries with a revisit | " << m.n_frames << " / " << m.n_queries << " / "
     << m.n_revisit_queries << " |\n| scored pairs: positive / negative | " << main.n_positive << " / "
     << main.n_negative << " |\n| detected loops: true / false / 3–20 m | " << m.loops_true << " / "
     << m.loops_false << " / " << m.loops_lateral
     << " |\n| detected loops with a correct pose (RTE < " << fixed(options.success_translation, 0) << " m, RRE < "
     << fixed(options.success_rotation, 0) << "°), at any distance: all / false | " << m.loops_pose_correct << " of "
     << m.loops_detected << " / " << m.loops_false_pose_correct << " of " << m.loops_false
     << " |\n| pose success rate of loops within " << fixed(options.pose_max_distance, 0) << " m (RTE < "
     << fixed(options.success_translation, 0) << " m, RRE < " << fixed(options.success_rotation, 0) << "°)"
     << poseRows(m.poses) << "| ms per frame, median / p99 | "
     << fixed(m.ms_per_frame_median, 2) << " / " << fixed(m.ms_per_frame_p99, 2)
     << " |\n| database bytes per frame | " << fixed(m.db_bytes_per_frame, 0) << " |\n"
     << undefinedParagraph(undefinedMetrics(m)) << "\n";
  if (!run.contiguous) {
    md << "Note: frame numbers are not 0, 1, 2, …; the exclusion gap counted processed frames, not frame numbers.\n\n";
  }
  md << top1Section(m, options) << extra.section;
  md << "## Distance test\n\n| positive < | F1max | EP | positives |\n|---|---|---|---|\n";
  for (const CurveMetrics& c : m.pairwise) {
    md << "| " << fixed(c.positive_distance, 0) << " m | " << metricText(c.f1_max, c.defined(), 4) << " | "
       << metricText(c.ep, c.defined(), 4) << " | " << c.n_positive << " |\n";
  }
  md << "\nNegatives are pairs farther than " << fixed(options.negative_distance, 0)
     << " m; pairs in between are left out. No ICP overlap check is applied.\n\n"
     << "## Plots\n\n![PR curves](pr_curves.png)\n\n![trajectory](trajectory.png)\n\n![time per frame](timing.png)"
        "\n\n![database size](memory.png)\n\nTables: `pr_curve.csv`, `frames.csv`, `candidates.csv` (every scored "
        "pair); numbers: `metrics.json`.\n\n"
     << configSection(info);
  out.text("report.md", md.str());
}

void writePairListReport(const std::string& dir, const PairListRun& run, const PairListMetrics& m,
                         const ReportInfo& info, io::Overwrite overwrite) {
  const ReportWriter out{prepare(dir, pairListReportFiles(dir), overwrite), overwrite};
  out.text("metrics.json", pairListMetricsJson(m, run, 1000).dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
  out.text("pr_curve.csv", prCsv({{"pairs", &m.curve}}));
  std::ostringstream pairs;
  pairs << "query,candidate,label,available,loop,score,score_c,rte_m,rre_deg\n";
  for (const PairRecord& r : run.pairs) {
    pairs << r.pair.query << "," << r.pair.candidate << "," << r.pair.loop << "," << r.available << "," << r.is_loop
          << "," << r.score << "," << r.score_c << ",";
    if (r.pose_evaluated) pairs << r.pose_error.translation_m << "," << r.pose_error.rotation_deg;
    else pairs << ",";
    pairs << "\n";
  }
  out.text("pairs.csv", pairs.str());
  out.png("pr_curves.png", [&](const std::string& tmp) {
    plotPrCurves(tmp, {m.curve}, nullptr, "Precision-recall over the listed pairs");
  });

  std::ostringstream md;
  md << "# Loop-closure evaluation over a pair list\n\n" << provenance(info);
  md << pairListTable(m) << "\n![PR curve](pr_curves.png)\n\nPer pair: `pairs.csv`.\n\n"
     << configSection(info);
  out.text("report.md", md.str());
}

}  // namespace sgtllc::eval
