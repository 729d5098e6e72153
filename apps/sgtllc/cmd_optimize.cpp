// `sgtllc optimize --odometry ODOM --loops loops.csv`: the pose-graph back end alone, on the loops `sgtllc run`
// wrote, with trajectory errors against ground truth and the false-loop robustness test.
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "common.h"
#include "loop_closing.h"
#include "sgtllc/eval/false_loops.h"
#include "sgtllc/io/config_yaml.h"
#include "sgtllc/io/sequence.h"
#include "trajectory_metrics.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {
namespace {

struct OptimizeOptions {
  std::string odometry, loops, calib, frames, ground_truth, report, config;
  io::PoseFrame pose_frame = io::PoseFrame::kAuto;  ///< --pose-frame of a KITTI --odometry
  ClosingOutputs outputs;
  double false_fraction = 0.0;
  uint64_t seed = 7;
  int threads = 0;
  bool json = false;
  bool force = false;
};

const std::vector<std::string> kReportFiles = {"report.md", "metrics.json", "trajectory_topview.png",
                                               "corrected_trajectory.txt"};

/// Frame i's name: the i-th file of --frames (a sequence or node folder), else its number as KITTI writes it.
std::vector<std::string> frameNames(const std::string& frames, size_t count, const Config& config) {
  std::vector<std::string> names;
  if (!frames.empty()) {
    // A folder of scans (velodyne/, or .bin/.pcd/.ply files: io/sequence.h) names frames by its scans, read
    // without labels (only the names count); any other folder by its node files.
    std::error_code ec;
    bool scans = fs::is_directory(fs::path(frames) / "velodyne", ec);
    for (fs::directory_iterator it(frames, ec), end; !scans && !ec && it != end; it.increment(ec)) {
      scans = io::scanFormatOf(it->path().string()).has_value();
    }
    if (scans) {
      const io::SequenceDir seq(frames, io::SequenceLabels{false, "", config.labels.format});
      for (size_t i = 0; i < seq.size(); ++i) names.push_back(seq.frameName(i));
      return names;
    }
    const pipeline::FrameSource source = pipeline::FrameSource::nodeFiles(frames, config);
    for (size_t i = 0; i < source.size(); ++i) names.push_back(source.name(i));
    return names;
  }
  char buf[32];
  for (size_t i = 0; i < count; ++i) {
    std::snprintf(buf, sizeof(buf), "%06zu", i);
    names.emplace_back(buf);
  }
  return names;
}

void writeReport(const OptimizeOptions& o, const Config& config, const Json& metrics, const std::string& summary,
                 const std::string& section, const std::vector<Eigen::Isometry3d>& truth, const Odometry& odometry,
                 const std::vector<ClosingLoop>& loops, const Closing& closing) {
  std::error_code ec;
  fs::create_directories(o.report, ec);
  if (ec) throw Error("cannot create report folder " + o.report + ": " + ec.message());
  const fs::path dir(o.report);
  io::writeTrajectory((dir / "corrected_trajectory.txt").string(), io::withPoses(odometry.trajectory, closing.poses),
                      io::overwriteIf(o.force));
  writeOutput((dir / "metrics.json").string(), jsonText(metrics) + "\n", o.force);
  plotClosing((dir / "trajectory_topview.png").string(), truth, odometry, loops, closing);
  std::string md = "# Loop closing: pose-graph optimisation\n\nOdometry `" + o.odometry + "`, loops `" + o.loops +
                   "`" + (o.ground_truth.empty() ? "" : ", ground truth `" + o.ground_truth + "`") +
                   ".\n\nCommand:\n\n```sh\n" + commandLine() + "\n```\n\n## Back end\n\n```\n" + summary +
                   "```\n\n";
  md += section.empty() ? "![trajectories, top view](trajectory_topview.png)\n\n" : section;
  md += "Corrected trajectory: `corrected_trajectory.txt` (format and frame of the odometry); numbers: "
        "`metrics.json`.\n\n## Configuration\n\n```yaml\n" + io::configToYaml(config) + "```\n";
  writeOutput((dir / "report.md").string(), md, o.force);
}

void runOptimize(const OptimizeOptions& o) {
  const Config config = loadConfigOption(o.config, o.threads);
  checkClosingOutputs(o.outputs, o.force);
  if (!o.report.empty()) checkReportFiles(o.report, kReportFiles, o.force);

  const Odometry odometry = readOdometry(o.odometry, o.calib, o.pose_frame, 0);
  const std::vector<std::string> names = frameNames(o.frames, odometry.poses.size(), config);
  io::checkPoseCount(o.odometry, odometry.trajectory, names.size());
  std::vector<Eigen::Isometry3d> truth;
  if (!o.ground_truth.empty()) {
    // With --calib the ground truth is read by the auto rule (KITTI's poses are cam0), so LiDAR-frame odometry
    // (--pose-frame lidar) can be compared with it; without one it is in the frame --pose-frame gives.
    const io::PoseFrame frame = o.calib.empty() ? o.pose_frame : io::PoseFrame::kAuto;
    truth = readOdometry(o.ground_truth, o.calib, frame, names.size()).poses;
  }
  std::vector<ClosingLoop> loops = pipeline::csvLoops(io::readLoopsCsv(o.loops, names), config.backend.loops);
  const size_t real = loops.size();
  for (ClosingLoop& l :
       eval::falseLoops(odometry.poses, loops, o.false_fraction, o.seed, names, config.backend.loops)) {
    loops.push_back(std::move(l));
  }

  const Closing closing = pipeline::closeLoopsBatch(odometry.poses, loops, config.backend);
  writeClosingOutputs(o.outputs, odometry, loops, closing, config, o.force);

  Json out = {{"odometry", o.odometry}, {"frames", names.size()}, {"loops_read", real},
              {"backend", closingJson(loops, closing)}};
  std::string section;
  std::string text = closingSummary(loops, closing);
  if (!truth.empty()) {
    const TrajectoryComparison c = compareTrajectories(truth, odometry, closing);
    out["trajectory"] = comparisonJson(c);
    text += comparisonText(c);
    section = comparisonMarkdown(c, "trajectory_topview.png");
  }
  if (!o.report.empty()) writeReport(o, config, out, text, section, truth, odometry, loops, closing);
  if (o.json) {
    std::cout << jsonText(out) << "\n";
    return;
  }
  std::cout << "frames " << names.size() << ", loops read " << real << "\n" << text;
  for (const std::string* path : {&o.outputs.trajectory, &o.outputs.graph, &o.outputs.loops}) {
    if (!path->empty()) std::cout << "wrote " << *path << "\n";
  }
  if (!o.report.empty()) std::cout << "report: " << (fs::path(o.report) / "report.md").string() << "\n";
}

}  // namespace

void addOptimizeCommand(CLI::App& app) {
  auto o = std::make_shared<OptimizeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "optimize", "Pose-graph optimisation of an odometry with the loops of `sgtllc run --out` (outliers rejected)");
  cmd->add_option("--odometry", o->odometry, "odometry, one pose per frame: KITTI (12 columns) or TUM (8 columns)")
      ->required();
  cmd->add_option("--loops", o->loops, "loops CSV written by `sgtllc run --out`")->required();
  cmd->add_option("--calib", o->calib, "KITTI calib.txt: its Tr converts KITTI poses (odometry, ground truth) to LiDAR");
  addPoseFrameOption(*cmd, o->pose_frame, "--odometry (and of --ground-truth when there is no --calib)");
  cmd->add_option("--frames", o->frames,
                  "sequence folder (velodyne/, or .bin/.pcd/.ply scans) or node folder whose file names the CSV uses (default: frame i is "
                  "named by its 6-digit number, 000000, 000001, ...)");
  addClosingOutputOptions(*cmd, o->outputs);
  cmd->add_option("--ground-truth", o->ground_truth,
                  "ground-truth trajectory (KITTI or TUM, through --calib): report ATE and RPE of both trajectories");
  cmd->add_option("--report", o->report,
                  "write report.md, metrics.json, trajectory_topview.png, corrected_trajectory.txt to this folder");
  cmd->add_option("--add-false-loops", o->false_fraction,
                  "robustness test: add this share of false loops (random frame pairs > 50 m apart, random poses)")
      ->check(CLI::Range(0.0, 10.0));
  cmd->add_option("--seed", o->seed, "seed of --add-false-loops (default 7)");
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`, keys backend.*)");
  cmd->add_option("--threads", o->threads, "solver threads (default: the config's backend.solver.num_threads)")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_flag("--json", o->json, "print the summary (and trajectory errors) as one JSON object");
  cmd->add_flag("--force", o->force, "overwrite existing output files");
  cmd->callback([o] {
    checkPoseFrameOptions("optimize", o->calib, o->pose_frame, !o->ground_truth.empty());
    runOptimize(*o);
  });
}

}  // namespace sgtllc::cli
