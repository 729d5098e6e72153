// `sgtllc run SEQ_DIR` / `sgtllc run --nodes NODE_DIR`: streams a sequence through the online detector.
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "accumulation.h"
#include "commands.h"
#include "common.h"
#include "loop_closing.h"
#include "run_session.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/pipeline/loop_closing_pipeline.h"
#include "sgtllc/eval/ground_truth.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/io/loops_csv.h"
#include "sgtllc/io/output_file.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/map/map_file.h"

namespace sgtllc::cli {
namespace {


using Loop = io::LoopRecord;

/// Said once, before the run: a sequence of at most LoopDetector::firstSearchedFrame() frames cannot have a loop.
void noteShortSequence(const std::string& name, size_t frames, const Config& config) {
  const RetrievalConfig& rc = config.retrieval;
  std::cerr << "note: " << name << " has " << frames << (frames == 1 ? " frame" : " frames")
            << ", so no frame can have loop candidates: ";
  if (frames < 2) {
    std::cerr << "a loop needs at least two frames.\n";
  } else if (rc.warmup_frames > rc.exclude_recent) {
    std::cerr << "no frame is searched before retrieval.warmup_frames = " << rc.warmup_frames
              << ". Lower retrieval.warmup_frames in a --config file to search this sequence.\n";
  } else {
    std::cerr << "a frame is compared only with frames at least retrieval.exclude_recent = " << rc.exclude_recent
              << " older. Set retrieval.exclude_recent below " << frames
              << " in a --config file to search this sequence.\n";
  }
}

/// Poses a saved map places its frames by (T_world_lidar) when there is no --odometry (then the corrected
/// trajectory is stored): SEQ_DIR/poses.txt with its calib.txt when both exist (frames named by their line), else
/// none. A --nodes folder holds only node files, so its poses come from --odometry. @p from says which.
std::vector<Eigen::Matrix4d> sequencePoses(const RunOptions& o, const pipeline::FrameSource& source, std::string* from) {
  namespace fs = std::filesystem;
  std::vector<Eigen::Matrix4d> poses;
  *from = "none (give --odometry, or a SEQ_DIR with poses.txt and calib.txt)";
  if (o.sequence.empty()) return poses;
  const fs::path dir(o.sequence);
  const std::string truth_path = (dir / "poses.txt").string(), calib = (dir / "calib.txt").string();
  if (!fs::is_regular_file(truth_path) || !fs::is_regular_file(calib)) return poses;
  const eval::GroundTruth truth = eval::GroundTruth::fromKitti(truth_path, calib);
  for (size_t i = 0; i < source.size(); ++i) {
    if (!truth.has(source.number(i))) {
      throw Error(truth_path + ": no pose for frame " + io::quoteContent(source.name(i)) + " (" + std::to_string(truth.size()) +
                  " lines; frames must be named by their line number), so --save-map cannot place the frames; "
                  "give --odometry");
    }
    poses.push_back(truth.pose(source.number(i)));
  }
  *from = truth_path;
  return poses;
}

void runSequence(const RunOptions& o) {
  const Config config = loadConfigOption(o.config, o.threads, o.labeller);
  // Checked now, so a bad path fails before the run; the final rename checks again (io/output_file.h).
  if (!o.out.empty()) checkWritable(o.out, o.force);
  checkClosingOutputs(o.outputs, o.force);
  if (!o.save_map.empty()) checkWritable(o.save_map, o.force);
  pipeline::FrameSource source = frameSource(o.sequence, o.nodes, config, o.labels_dir);
  std::unique_ptr<Odometry> odometry;
  if (!o.odometry.empty()) {
    odometry = std::make_unique<Odometry>(
        readOdometry(o.odometry, sequenceCalib(o.calib, o.sequence), o.pose_frame, source.size()));
  }
  applyAccumulation(source, o.accumulate, odometry.get(), o.sequence, o.calib, o.pose_frame);
  AccumulationCost accumulation;
  std::string poses_from;
  std::vector<Eigen::Matrix4d> map_poses;
  if (!o.save_map.empty() && !odometry) map_poses = sequencePoses(o, source, &poses_from);
  pipeline::PipelineOptions options;
  options.online = o.online;  // the options' check: --online needs --odometry
  pipeline::LoopClosingPipeline closer(config, options);
  if (source.size() <= static_cast<size_t>(closer.detector().firstSearchedFrame())) {
    noteShortSequence(o.nodes.empty() ? o.sequence : o.nodes, source.size(), config);
  }

  std::vector<double> frame_ms, load_ms;
  Progress progress("frames", source.size());
  UnknownLabels unknown;
  pipeline::streamFrames(source, config.threads, [&](size_t index, pipeline::LoadedFrame& loaded) {
    load_ms.push_back(loaded.load_ms);
    accumulation.add(loaded);
    ExtractionStats stats = loaded.stats;
    std::optional<Eigen::Isometry3d> pose;
    if (odometry) pose = odometry->trajectory.poses[index];  // the pipeline orthonormalises it as readOdometry does
    const pipeline::PipelineFrame f = closer.addFrame(std::move(loaded), pose, source.name(index));
    frame_ms.push_back(f.detection.timing.total_ms());
    // Unknown label ids (a network's label space, a wrong labels.preset) are summed into one warning at the end.
    unknown.add(source.name(index), stats.unknown_label_points);
    stats.unknown_label_points = 0;
    if (stats.nonfinite_points > 0 || stats.far_points > 0 || stats.capped_nodes > 0) {
      progress.clear();
      warnAboutInput(source.name(index), stats, f.detection.num_nodes);
    }
    if (f.loop && !o.json && !o.quiet) {
      progress.clear();
      const Eigen::Vector3d t = f.loop->edge.T_from_to.translation();
      std::cout << "loop " << io::escapeContent(f.loop->query, io::kNameBytes) << " -> "
                << io::escapeContent(f.loop->match, io::kNameBytes) << "  score " << fixed(f.loop->score, 3)
                << "  score_c " << fixed(f.loop->score_c, 3) << "  t = (" << fixed(t.x(), 2) << ", "
                << fixed(t.y(), 2) << ", " << fixed(t.z(), 2) << ") m"
                << (f.detection.lateral ? "  lateral (a neighbour of the revisit)" : "") << "\n";
      if (f.solved) std::cout << onlineUpdateLine(*f.update, f.solve_ms);
      std::cout << std::flush;
    }
    progress.update(index + 1, std::to_string(closer.loops().size()) + " loops");
  });
  progress.finish();
  unknown.warn();
  std::vector<Loop> loops;
  for (const pipeline::ClosingLoop& l : closer.loops()) loops.push_back(pipeline::loopRecord(l));
  const Closing* closing = nullptr;
  if (odometry) {
    closing = &closer.finish();
    writeClosingOutputs(o.outputs, *odometry, closer.loops(), *closing, config, o.force);
    poses_from = "the corrected trajectory of " + odometry->path;
  }
  if (!o.out.empty()) writeOutput(o.out, io::loopsCsvText(loops, true), o.force);
  if (!o.save_map.empty()) {
    // With --odometry the map holds the corrected trajectory (the pipeline's poses), else SEQ_DIR's, or none.
    std::optional<std::vector<Eigen::Matrix4d>> placed;
    if (!odometry) placed = std::move(map_poses);
    map::writeMapFile(o.save_map, closer.map(std::move(placed)), io::overwriteIf(o.force));
  }

  const int n = closer.detector().numFrames();
  const double bytes_per_frame = n ? static_cast<double>(closer.detector().database().totalBytes()) / n : 0.0;
  if (o.json) {
    Json list = Json::array();
    for (const Loop& l : loops) {
      list.push_back({{"query", l.query},
                      {"match", l.match},
                      {"score", l.score},
                      {"score_t", l.score},
                      {"score_c", l.score_c},
                      {"T_match_query", matrixJson(l.T_match_query)}});
    }
    Json out = {{"sequence", o.nodes.empty() ? o.sequence : o.nodes},
                {"frames", n},
                {"loops", loops.size()},
                {"ms_per_frame_median", eval::percentile(frame_ms, 0.5)},
                {"ms_per_frame_p99", eval::percentile(frame_ms, 0.99)},
                {"load_ms_median", eval::percentile(load_ms, 0.5)},
                {"db_bytes_per_frame", bytes_per_frame},
                {"loop_list", list}};
    if (o.accumulate > 1) out["accumulation"] = accumulation.json(o.accumulate);
    if (closing) out["backend"] = closingJson(closer.loops(), *closing);
    if (!o.save_map.empty()) out["map"] = {{"path", o.save_map}, {"poses", poses_from}};
    std::cout << jsonText(out) << "\n";
  } else {
    std::cout << "frames " << n << ", loops " << loops.size() << ", ms per frame: median "
              << fixed(eval::percentile(frame_ms, 0.5), 2) << ", p99 " << fixed(eval::percentile(frame_ms, 0.99), 2)
              << " (load (not included): median " << fixed(eval::percentile(load_ms, 0.5), 2) << " ms), database "
              << fixed(bytes_per_frame, 0) << " bytes per frame\n";
    if (o.accumulate > 1) std::cout << accumulation.text(o.accumulate);
    if (closing) std::cout << closingSummary(closer.loops(), *closing);
    for (const std::string* path : {&o.out, &o.outputs.trajectory, &o.outputs.graph, &o.outputs.loops}) {
      if (!path->empty()) std::cout << "wrote " << *path << "\n";
    }
    if (!o.save_map.empty()) std::cout << "wrote map " << o.save_map << " (" << n << " frames; poses: " << poses_from << ")\n";
  }
}

}  // namespace

void addRunCommand(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Stream a sequence (scans, their labels unless --labeller geometric, or node files) through the online detector");
  cmd->add_option("SEQ_DIR", o->sequence, kSequenceFolderHelp);
  cmd->add_option("--nodes", o->nodes,
                  "instead of SEQ_DIR: a folder of node files NAME.txt (x y z label rows), frames in name order");
  cmd->add_option("--out", o->out,
                  "write the detected loops as CSV (query,match,score,score_c, 3x4 pose, 21 information entries)");
  cmd->add_option("--odometry", o->odometry,
                  "close the loop: optimise this odometry (KITTI or TUM, one pose per frame) with the loops");
  cmd->add_option("--calib", o->calib,
                  "KITTI calib.txt for a KITTI --odometry (or poses.txt, with --accumulate) in cam0 (default: "
                  "SEQ_DIR/calib.txt if it exists)");
  addPoseFrameOption(*cmd, o->pose_frame, "--odometry (without it: of SEQ_DIR/poses.txt for --accumulate)");
  addAccumulateOption(*cmd, o->accumulate);
  cmd->add_option("--save-map", o->save_map,
                  "save the database as a map file for `sgtllc localize` (frames named as the input; poses: the "
                  "corrected --odometry trajectory, else SEQ_DIR/poses.txt with calib.txt when present)");
  addClosingOutputOptions(*cmd, o->outputs);
  cmd->add_option("--map", o->map,
                  "run SEQ_DIR as a new session against this map (needs --odometry): its frames are searched in the map "
                  "and among its own, and one pose graph places it in the map's frame with the map's poses fixed; "
                  "--out-trajectory is then in the map's frame and --save-map writes the merged map (docs/sessions.md)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--session-name", o->session_name,
                  "with --map: the session's name in the merged map, its frames named NAME/FRAME (default: the "
                  "folder's name)");
  cmd->add_option("--add-false-loops", o->false_fraction,
                  "with --map, robustness test: add this share of false inter-session loops (a session frame with an "
                  "inter-session loop tied to a map frame > 50 m from it, a random pose); each must be rejected")
      ->check(CLI::Range(0.0, 10.0));
  cmd->add_option("--seed", o->seed, "seed of --add-false-loops (default 7)");
  cmd->add_flag("--online", o->online,
                "re-optimise at every loop, as a robot would, and print each update (default: once at the end)");
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`)");
  addLabellerOption(cmd, &o->labeller);
  cmd->add_option("--labels-dir", o->labels_dir,
                  "read DIR/NNNNNN.label (e.g. a segmentation network's predictions) instead of SEQ_DIR/labels");
  cmd->add_option("--threads", o->threads, "worker threads (default: the config's `threads`)")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_flag("--json", o->json, "print the summary and the loops as one JSON object");
  cmd->add_flag("--quiet", o->quiet, "print the summary only, no line per loop (or per --online update)");
  cmd->add_flag("--force", o->force, "overwrite existing output files");
  cmd->callback([o] {
    if (o->sequence.empty() == o->nodes.empty()) {
      throw CLI::ValidationError("run", "give either SEQ_DIR (scans: velodyne/*.bin, or .bin/.pcd/.ply files) or --nodes NODE_DIR");
    }
    const bool closes = !o->outputs.trajectory.empty() || !o->outputs.graph.empty() || !o->outputs.loops.empty() ||
                        (!o->calib.empty() && o->accumulate == 1) || o->online;
    if (closes && o->odometry.empty()) {
      throw CLI::ValidationError("run", "--out-trajectory, --out-graph, --out-loops, --calib (without --accumulate) "
                                        "and --online need --odometry");
    }
    checkPoseFrameOptions("run", o->calib, o->pose_frame);
    if (o->accumulate > 1 && !o->nodes.empty()) {
      throw CLI::ValidationError("run", "--accumulate merges scans: give SEQ_DIR, not --nodes");
    }
    if (!o->map.empty()) {
      if (o->odometry.empty()) throw CLI::ValidationError("run", "--map needs the session's --odometry");
      if (o->online || !o->outputs.graph.empty() || !o->outputs.loops.empty()) {
        throw CLI::ValidationError("run", "--online, --out-graph and --out-loops do not work with --map yet");
      }
      runSession(*o);
      return;
    }
    if (!o->session_name.empty() || o->false_fraction > 0.0) {
      throw CLI::ValidationError("run", "--session-name and --add-false-loops go with --map (one drive's robustness "
                                        "test is `sgtllc optimize --add-false-loops`)");
    }
    runSequence(*o);
  });
}

}  // namespace sgtllc::cli
