// `sgtllc eval SEQ_DIR`: the paper's protocol on a sequence (or a pair list), with a report.
#include <filesystem>
#include <iostream>
#include <memory>

#include "accumulation.h"
#include "build_info.h"
#include "commands.h"
#include "common.h"
#include "localization.h"
#include "loop_closing.h"
#include "merge_eval.h"
#include "relocalization_eval.h"
#include "trajectory_metrics.h"
#include "sgtllc/eval/metric_text.h"
#include "sgtllc/eval/report.h"
#include "sgtllc/io/config_yaml.h"
#include "sgtllc/io/output_file.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {
namespace {

struct EvalCliOptions {
  std::string sequence, pairs, nodes, report, config;
  std::string labeller, labels_dir;  ///< --labeller, --labels-dir (as `sgtllc run`)
  std::string odometry, calib;  ///< --odometry: also close the loop and report trajectory errors
  io::PoseFrame pose_frame = io::PoseFrame::kAuto;  ///< --pose-frame of a KITTI --odometry (or poses.txt)
  std::string map;              ///< --map: the relocalization protocol in this map instead
  ClosingOutputs outputs;
  int threads = 0;
  int accumulate = 1;  ///< --accumulate: scans merged into each frame
  bool json = false;
  bool force = false;
  bool no_pairs = false;  ///< --no-pairs: skip the folder's loop_pairs.txt
  bool track = false;     ///< --track (with --map): the query frames are one stream
  std::string command;
};

/// poses.txt + calib.txt of the sequence; an empty GroundTruth if @p required is false and poses.txt is absent.
eval::GroundTruth loadTruth(const std::string& dir, bool required) {
  const std::string poses = (fs::path(dir) / "poses.txt").string();
  const std::string calib = (fs::path(dir) / "calib.txt").string();
  if (!fs::exists(poses)) {
    if (required) throw Error(poses + ": missing (sequence evaluation needs ground-truth poses and calib.txt)");
    return {};
  }
  return eval::GroundTruth::fromKitti(poses, calib);
}

/// Before any work: every file the report would write must be new (or --force), its folder creatable. The report
/// writer checks again, and each file's final rename refuses one that appeared meanwhile.
void checkReportFolder(const EvalCliOptions& o) {
  if (o.report.empty()) return;
  if (fs::exists(o.report) && !fs::is_directory(o.report)) throw Error(o.report + ": exists and is not a folder");
  const auto files = o.pairs.empty() ? eval::sequenceReportFiles(o.report) : eval::pairListReportFiles(o.report);
  io::checkOutputFiles(files, io::overwriteIf(o.force), true);
}

std::string summaryLine(const char* name, double value, bool defined = true) {
  return std::string(name) + " " + eval::metricText(value, defined, 4);
}

/// "pose success RATE (S of N ...), mean RTE X m, RRE Y deg" with n/a where undefined.
std::string poseLine(const eval::PoseSummary& p) {
  return "pose success " + eval::metricText(p.success_rate, p.rateDefined(), 4) + " (" +
         std::to_string(p.successes) + " of " + std::to_string(p.evaluated) + "), mean RTE " +
         eval::metricText(p.rte_mean, p.meansDefined(), 3) + " m, RRE " +
         eval::metricText(p.rre_mean, p.meansDefined(), 3) + " deg";
}

/// The pair-list protocol's terminal lines.
std::string pairListSummary(const eval::PairListMetrics& m) {
  std::string out = "pairs " + std::to_string(m.n_pairs) + ", scored " + std::to_string(m.n_available) +
                    " (both frames present), positives " + std::to_string(m.curve.n_positive) + ", negatives " +
                    std::to_string(m.curve.n_negative) + " (" + std::to_string(m.positives_scored_zero) +
                    " positives scored 0)\ndecisions equal to the label: " + std::to_string(m.correct) + " of " +
                    std::to_string(m.n_available) + "\n" + summaryLine("F1max", m.curve.f1_max, m.curve.defined()) +
                    ", " + summaryLine("EP", m.curve.ep, m.curve.defined()) + ", " +
                    summaryLine("recall@100%precision", m.curve.recall_at_100_precision, m.curve.defined()) +
                    "\npose: " + std::to_string(m.poses.successes) + " of " + std::to_string(m.poses.evaluated) +
                    " detected true loops within 2 m / 5 deg";
  if (m.poses.successes) {
    out += ", mean RTE " + fixed(m.poses.rte_mean, 3) + " m, RRE " + fixed(m.poses.rre_mean, 3) + " deg";
  }
  return out + "\n" + eval::undefinedText(eval::undefinedMetrics(m));
}

/// "Only N of M listed pairs ..." when some listed frames are not in the input, else "".
std::string pairListNote(const eval::PairListRun& run, const eval::PairListMetrics& m) {
  if (run.unavailable == 0) return "";
  return "Only " + std::to_string(m.n_available) + " of " + std::to_string(m.n_pairs) +
         " listed pairs have both frames in the input; the metrics cover those pairs only.";
}

const std::vector<std::string> kClosingReportFiles = {"trajectory_topview.png", "corrected_trajectory.txt"};

/// The back end's part of `eval --odometry`: loop edges collected while the protocol runs, optimised at the end
/// and compared with the sequence's ground truth.
struct EvalClosing {
  std::unique_ptr<Odometry> odometry;
  std::vector<ClosingLoop> loops;
  Closing closing;
  std::vector<Eigen::Isometry3d> truth;
  TrajectoryComparison comparison;
  std::string summary;

  void finish(const eval::SequenceRun& run, const eval::GroundTruth& truth_poses, const Config& config) {
    closing = pipeline::closeLoopsBatch(odometry->poses, loops, config.backend);
    for (const eval::FrameRecord& f : run.frames) truth.emplace_back(truth_poses.pose(f.frame));
    comparison = compareTrajectories(truth, *odometry, closing);
    summary = closingSummary(loops, closing);
  }
  Json json() const { return {{"backend", closingJson(loops, closing)}, {"trajectory", comparisonJson(comparison)}}; }
  std::string section() const {
    return "## Loop closing\n\n```\n" + summary + "```\n\n" + comparisonMarkdown(comparison, "trajectory_topview.png");
  }
  void writeReportFiles(const std::string& dir, bool force) const {
    io::writeTrajectory((fs::path(dir) / "corrected_trajectory.txt").string(),
                        io::withPoses(odometry->trajectory, closing.poses), io::overwriteIf(force));
    plotClosing((fs::path(dir) / "trajectory_topview.png").string(), truth, *odometry, loops, closing);
  }
};

/// The pair-list protocol on the sequence folder's loop_pairs.txt (the simulator writes one), run after the
/// online protocol on the nodes it stored, so one `sgtllc eval SEQ` reports all three protocols.
struct FolderPairs {
  std::string path;  ///< empty: no loop_pairs.txt, --pairs given, or --no-pairs
  std::vector<eval::LoopPairLabel> pairs;
  std::vector<long> numbers;
  std::vector<std::vector<Node>> nodes;
  std::vector<Footprint> footprints;  ///< the footprint check of the pair list, as online
  eval::PairListRun run;
  eval::PairListMetrics metrics;

  FolderPairs(const EvalCliOptions& o, eval::EvalOptions& options) {
    const fs::path file = fs::path(o.sequence) / "loop_pairs.txt";
    if (!o.pairs.empty() || o.no_pairs || !fs::exists(file)) return;
    // Before the run, so that a malformed list fails fast. A list without pairs (a simulated sequence without
    // revisits) has nothing to score: said once and skipped, not an error as for an explicit --pairs.
    pairs = eval::readPairList(file.string(), /*allow_empty=*/true);
    if (pairs.empty()) {
      std::cerr << "note: " << file.string() << " lists no pairs; the pair-list protocol is skipped\n";
      return;
    }
    path = file.string();
    auto chained = options.on_frame;
    options.on_frame = [this, chained](size_t i, const FrameResult& r, const LoopDetector& detector) {
      nodes.push_back(detector.database().nodes(r.frame));
      footprints.push_back(detector.footprints()[static_cast<size_t>(r.frame)]);
      numbers.push_back(static_cast<long>(i));
      if (chained) chained(i, r, detector);
    };
  }
  bool active() const { return !path.empty(); }
  void finish(const eval::SequenceRun& seq, const eval::GroundTruth& truth, const Config& config,
              const eval::EvalOptions& options, eval::ReportExtra& extra) {
    if (!active()) return;
    for (size_t i = 0; i < numbers.size(); ++i) numbers[i] = seq.frames[i].frame;
    eval::EvalOptions quiet = options;
    quiet.progress = nullptr;
    run = eval::runPairListEvaluation(numbers, nodes, pairs, truth, config, quiet, footprints);
    metrics = eval::computePairListMetrics(run, options);
    extra.metrics["pair_list"] = json();
    extra.section += eval::pairListSection(metrics, path, pairListNote(run, metrics));
  }
  Json json() const {
    Json j = eval::pairListMetricsJson(metrics, run, 0);
    j["file"] = path;
    return j;
  }
};

void runEval(const EvalCliOptions& o) {
  const Config config = loadConfigOption(o.config, o.threads, o.labeller);
  checkReportFolder(o);
  EvalClosing back;
  if (!o.odometry.empty()) {
    if (!o.report.empty()) checkReportFiles(o.report, kClosingReportFiles, o.force);
    checkClosingOutputs(o.outputs, o.force);
  }
  pipeline::FrameSource source = frameSource(o.sequence, o.nodes, config, o.labels_dir);
  eval::EvalOptions options;
  options.threads = config.threads;
  Progress progress("frames", source.size());
  options.progress = [&progress](size_t done, size_t, int loops) {
    progress.update(done, std::to_string(loops) + " loops");
  };
  eval::ReportInfo info = runInfo();
  info.input = o.nodes.empty() ? o.sequence : o.nodes;
  info.pairs_file = o.pairs;
  info.command = o.command;
  info.config_yaml = io::configToYaml(config);
  eval::ReportExtra extra;
  if (!o.odometry.empty()) {
    back.odometry = std::make_unique<Odometry>(
        readOdometry(o.odometry, sequenceCalib(o.calib, o.sequence), o.pose_frame, source.size()));
    options.on_frame = [&](size_t i, const FrameResult& r, const LoopDetector& detector) {
      if (const Candidate* c = r.loop()) {
        back.loops.push_back(pipeline::detectedLoop(static_cast<int>(i), *c, detector.database(), source.name(i),
                                                    source.name(static_cast<size_t>(c->frame)), config.backend.loops));
      }
    };
  }
  applyAccumulation(source, o.accumulate, back.odometry.get(), o.sequence, o.calib, o.pose_frame);

  UnknownLabels unknown;  // one warning per run, not one per frame
  options.on_frame = [&unknown, &source, chained = options.on_frame](size_t i, const FrameResult& r,
                                                                     const LoopDetector& detector) {
    unknown.add(source.name(i), r.extraction.unknown_label_points);
    if (chained) chained(i, r, detector);
  };

  if (!o.pairs.empty()) {
    const auto pairs = eval::readPairList(o.pairs);
    const eval::GroundTruth truth = loadTruth(o.sequence, false);
    options.progress = nullptr;  // pairs are scored in parallel; no per-frame progress
    const eval::PairListRun run = eval::runPairListEvaluation(source, pairs, truth, config, options);
    const eval::PairListMetrics m = eval::computePairListMetrics(run, options);
    info.data_note = pairListNote(run, m);
    if (!o.report.empty()) eval::writePairListReport(o.report, run, m, info, io::overwriteIf(o.force));
    if (o.json) {
      std::cout << jsonText(eval::pairListMetricsJson(m, run)) << "\n";
      return;
    }
    std::cout << pairListSummary(m);
  } else {
    const eval::GroundTruth truth = loadTruth(o.sequence, true);
    FolderPairs folder_pairs(o, options);
    const eval::SequenceRun run = eval::runSequenceEvaluation(source, truth, config, options);
    progress.finish();
    unknown.warn();
    const eval::SequenceMetrics m = eval::computeSequenceMetrics(run, options);
    folder_pairs.finish(run, truth, config, options, extra);
    if (back.odometry) {
      back.finish(run, truth, config);
      writeClosingOutputs(o.outputs, *back.odometry, back.loops, back.closing, config, o.force);
      extra.section = back.section();
      extra.metrics = back.json();
    }
    if (!o.report.empty()) {
      eval::writeSequenceReport(o.report, run, m, options, info, extra, io::overwriteIf(o.force));
      if (back.odometry) back.writeReportFiles(o.report, o.force);
    }
    if (o.json) {
      Json j = eval::sequenceMetricsJson(m);
      for (const auto& [key, value] : extra.metrics.items()) j[key] = value;
      std::cout << jsonText(j) << "\n";
      return;
    }
    const eval::CurveMetrics& main = m.pairwise.at(0);
    std::cout << "frames " << m.n_frames << ", queries " << m.n_queries << " (" << m.n_revisit_queries
              << " with a revisit < 3 m), scored pairs " << main.n_positive << " positive / " << main.n_negative
              << " negative\n"
              << summaryLine("F1max", main.f1_max, main.defined()) << ", "
              << summaryLine("EP", main.ep, main.defined()) << ", "
              << summaryLine("recall@100%precision", main.recall_at_100_precision, main.defined()) << ", "
              << summaryLine("retrieval recall@15", m.retrieval_recall, m.n_revisit_queries > 0) << "\n"
              << "top-1 per query: " << m.top1_counts.near << " < 3 m, " << m.top1_counts.lateral << " 3-20 m, "
              << m.top1_counts.far << " > 20 m, " << m.top1_counts.none << " without a candidate; "
              << summaryLine("F1max", m.top1.f1_max, m.top1.defined()) << ", "
              << summaryLine("EP", m.top1.ep, m.top1.defined()) << "; 3-20 m left out: "
              << summaryLine("F1max", m.top1_no_lateral.f1_max, m.top1_no_lateral.defined()) << ", "
              << summaryLine("EP", m.top1_no_lateral.ep, m.top1_no_lateral.defined()) << "; score alone: "
              << summaryLine("F1max", m.top1_score_only.f1_max, m.top1_score_only.defined()) << "\nloops detected " << m.loops_detected << " (true "
              << m.loops_true << ", false " << m.loops_false << ", 3-20 m " << m.loops_lateral << "; reported lateral "
              << m.loops_reported_lateral
              << "; with a correct pose at any distance " << m.loops_pose_correct << ", of the false "
              << m.loops_false_pose_correct << "); " << poseLine(m.poses) << "\n"
              << "ms per frame: median " << fixed(m.ms_per_frame_median, 2) << ", p99 " << fixed(m.ms_per_frame_p99, 2)
              << "; database " << fixed(m.db_bytes_per_frame, 0) << " bytes per frame\n"
              << (m.refinement.enabled ? eval::refinementLine(m.refinement) : std::string())
              << eval::undefinedText(eval::undefinedMetrics(m));
    if (folder_pairs.active()) std::cout << "pair list " << folder_pairs.path << ":\n" << pairListSummary(folder_pairs.metrics);
    if (back.odometry) std::cout << back.summary << comparisonText(back.comparison);
  }
  if (!o.report.empty()) std::cout << "report: " << (fs::path(o.report) / "report.md").string() << "\n";
}

}  // namespace

void addEvalCommand(CLI::App& app) {
  auto o = std::make_shared<EvalCliOptions>();
  CLI::App* cmd = app.add_subcommand("eval", "Precision/recall, F1max, EP and pose accuracy on a sequence or pair list");
  cmd->add_option("SEQ_DIR", o->sequence,
                  std::string(kSequenceFolderHelp) + "; with poses.txt (KITTI cam0 poses, line i = frame i) and "
                  "calib.txt (Tr)")
      ->required();
  cmd->add_option("--pairs", o->pairs, "evaluate these 'query candidate label' pairs instead of the online protocol");
  cmd->add_flag("--no-pairs", o->no_pairs,
                "without --pairs, the folder's loop_pairs.txt (if any) is scored too, on the frames already read; "
                "this skips it");
  cmd->add_option("--nodes", o->nodes, "read frames from node files NAME.txt (x y z label rows) in this folder");
  cmd->add_option("--report", o->report, "write report.md, metrics.json, CSV tables and PNG plots to this folder");
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`)");
  addLabellerOption(cmd, &o->labeller);
  cmd->add_option("--labels-dir", o->labels_dir,
                  "read DIR/NNNNNN.label (e.g. a segmentation network's predictions) instead of SEQ_DIR/labels");
  cmd->add_option("--threads", o->threads, "worker threads (default: the config's `threads`)")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_flag("--json", o->json, "print the metrics as one JSON object");
  cmd->add_option("--odometry", o->odometry,
                  "also close the loop: optimise this odometry (KITTI or TUM) with the detected loops and report "
                  "ATE/RPE of odometry and corrected trajectory against poses.txt");
  cmd->add_option("--calib", o->calib, "calib.txt for a KITTI --odometry (default: SEQ_DIR/calib.txt)");
  addPoseFrameOption(*cmd, o->pose_frame, "--odometry (without it: of SEQ_DIR/poses.txt for --accumulate)");
  addAccumulateOption(*cmd, o->accumulate);
  addClosingOutputOptions(*cmd, o->outputs);
  cmd->add_option("--map", o->map,
                  "the relocalization protocol instead: relocalize every frame in this map (`sgtllc run --save-map` "
                  "of an earlier session) and score against both sessions' poses (docs/relocalization.md); with "
                  "--odometry, merge the sequence into the map as `run --map` does and score the merge against "
                  "poses.txt (docs/sessions.md)");
  addTrackOption(cmd, &o->track);
  cmd->add_flag("--force", o->force, "overwrite an existing report in --report (and existing output files)");
  cmd->callback([o] {
    if (o->track && o->map.empty()) throw CLI::ValidationError("eval", "--track needs --map");
    if (o->odometry.empty() && ((!o->calib.empty() && o->accumulate == 1) || !o->outputs.trajectory.empty() ||
                                !o->outputs.graph.empty() || !o->outputs.loops.empty())) {
      throw CLI::ValidationError("eval", "--calib (without --accumulate), --out-trajectory, --out-graph and "
                                         "--out-loops need --odometry");
    }
    checkPoseFrameOptions("eval", o->calib, o->pose_frame);
    if (!o->odometry.empty() && !o->pairs.empty()) {
      throw CLI::ValidationError("eval", "--odometry needs the sequence protocol; drop --pairs");
    }
    if (o->accumulate > 1 && !o->nodes.empty()) {
      throw CLI::ValidationError("eval", "--accumulate merges scans: give SEQ_DIR without --nodes");
    }
    if (!o->map.empty() && !o->odometry.empty()) {
      if (!o->pairs.empty() || !o->report.empty() || o->track || !o->outputs.trajectory.empty() ||
          !o->outputs.graph.empty() || !o->outputs.loops.empty()) {
        throw CLI::ValidationError("eval", "--map with --odometry evaluates a merge alone: drop --pairs, --report, "
                                           "--track and the --out-* files (`sgtllc run --map` writes them)");
      }
      RunOptions run;
      run.sequence = o->sequence, run.nodes = o->nodes, run.labels_dir = o->labels_dir;
      run.odometry = o->odometry, run.calib = o->calib, run.pose_frame = o->pose_frame, run.map = o->map;
      run.accumulate = o->accumulate, run.json = o->json, run.quiet = true;
      evalMerge(run, loadConfigOption(o->config, o->threads, o->labeller));
      return;
    }
    if (!o->map.empty()) {
      if (!o->pairs.empty() || !o->odometry.empty() || !o->report.empty() || o->accumulate > 1) {
        throw CLI::ValidationError("eval", "--map runs the relocalization protocol alone: drop --pairs, --odometry, "
                                           "--report and --accumulate");
      }
      evalRelocalization(o->map, o->sequence, o->nodes, o->labels_dir,
                         loadConfigOption(o->config, o->threads, o->labeller), o->json, trackingOption(o->track));
      return;
    }
    o->command = commandLine();
    runEval(*o);
  });
}

}  // namespace sgtllc::cli
