// `sgtllc simulate --out DIR --frames N --seed S`: writes a simulated SemanticKITTI-layout sequence with revisits;
// with `--world-of S1`, a second session through S1's world (docs/relocalization.md).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numeric>
#include <thread>

#include <Eigen/LU>

#include "commands.h"
#include "common.h"
#include "sgtllc/eval/sequence_eval.h"
#include "sgtllc/sim/label_space.h"
#include "sgtllc/sim/manifest.h"
#include "sgtllc/sim/preview.h"
#include "sgtllc/sim/revisit_fit.h"
#include "sgtllc/sim/sequence_writer.h"

namespace sgtllc::cli {
namespace {

namespace fs = std::filesystem;

struct SimulateOptions {
  std::string out;
  std::string world_of;  ///< first session's folder ("" = a world of its own)
  bool follow = false;   ///< --follow: the second session drives only the first one's roads
  int frames = 0;
  uint64_t seed = 1;
  bool seed_given = false, scene_given = false;
  std::string scene = "urban";
  std::string sensor = "hdl64";
  std::string label_space = "semantickitti";
  int accumulate = 0;
  double label_noise = sim::kDefaultLabelNoise;
  int revisits = -1;
  int threads = 0;
  double odometry_drift = 1.0;
  bool force = false;
  bool no_preview = false;
};

/// eval::percentile in the values' own type, so counts print as integers.
template <typename T>
T percentile(const std::vector<T>& v, double q) {
  return static_cast<T>(eval::percentile(std::vector<double>(v.begin(), v.end()), q));
}

std::vector<int> totals(const std::vector<std::array<int, kNumPaperClasses>>& nodes) {
  std::vector<int> out;
  for (const auto& n : nodes) out.push_back(std::accumulate(n.begin(), n.end(), 0));
  return out;
}

std::string shares(const std::map<uint16_t, uint64_t>& classes) {
  uint64_t total = 0;
  std::vector<std::pair<uint64_t, uint16_t>> sorted;
  for (const auto& [id, c] : classes) {
    total += c;
    sorted.push_back({c, id});
  }
  std::sort(sorted.rbegin(), sorted.rend());
  std::string s;
  for (const auto& [c, id] : sorted) {
    if (!s.empty()) s += ", ";
    s += std::string(sim::semanticName(id)) + " " + fixed(100.0 * c / std::max<uint64_t>(1, total), 1) + "%";
  }
  return s;
}

void printSummary(const sim::Simulator& s, const sim::SequenceStats& st, const std::string& out, double seconds) {
  const auto& pts = st.points;
  const double mean = pts.empty() ? 0.0 : std::accumulate(pts.begin(), pts.end(), 0.0) / pts.size();
  std::cout << "wrote " << st.frames << " frames to " << out << " (" << sim::sceneName(s.config().scene) << ", "
            << sim::sensorName(s.config().sensor.kind) << ", seed " << s.config().seed << ", label noise "
            << fixed(s.config().label_noise, 2) << ") in " << fixed(seconds, 1) << " s, "
            << fixed(st.frames / std::max(seconds, 1e-9), 1) << " frames/s\n";
  std::cout << "points per frame: mean " << fixed(mean, 0) << ", min " << percentile(pts, 0.0) << ", max "
            << percentile(pts, 1.0) << "\n";
  std::cout << "labels written: " << shares(st.class_points) << "\n";
  if (!st.nodes.empty()) {
    const std::vector<int> noisy = totals(st.nodes), truth = totals(st.true_nodes);
    std::cout << "graph nodes per frame (default clustering, " << noisy.size() << " frames sampled): median "
              << percentile(noisy, 0.5) << " (10-90%: " << percentile(noisy, 0.1) << "-" << percentile(noisy, 0.9)
              << "); with true labels " << percentile(truth, 0.5) << "\n";
  }
  std::cout << "revisits: "
            << (s.isSecondSession() ? std::string("none planned (a second session)")
                                    : std::to_string(s.config().plannedRevisits()) + " planned")
            << "; " << st.query_frames
            << " frames have a loop within 3 m (" << st.opposite_queries << " facing the other way)";
  if (!st.lane_shift_offsets.empty()) {
    std::cout << "; " << st.lane_shift_offsets.size() << " frames one or two lanes aside, "
              << fixed(percentile(st.lane_shift_offsets, 0.5), 1) << " m from the earlier pass (median)";
  }
  std::cout << "\nframes by visit:";
  for (const auto& [kind, count] : st.frames_by_kind) std::cout << " " << sim::visitKindName(kind) << " " << count << ";";
  std::cout << "\nloop_pairs.txt: " << st.positives << " loops, " << st.negatives << " non-loops\n";
  if (s.isSecondSession()) {
    const double n = std::max(1, st.frames);
    std::cout << "second session in the world of seed " << s.config().world_of->seed << " ("
              << s.config().world_of->frames << " frames): " << st.cross_near << " frames ("
              << fixed(100.0 * st.cross_near / n, 1) << " %) have a first-session frame within 3 m, " << st.cross_far
              << " (" << fixed(100.0 * st.cross_far / n, 1) << " %) none within 20 m (cross_session.txt)\n";
  }
  std::cout << "odometry.txt: drifts " << fixed(st.odometry_end_error, 2) << " m by the last frame ("
            << fixed(100.0 * st.odometry_end_error / std::max(st.path_length, 1e-9), 2) << " % of "
            << fixed(st.path_length, 0) << " m driven)\n";
}

/// Said before writing: the route of a short sequence cannot hold every planned revisit.
void warnIfRevisitsDoNotFit(const sim::Simulator& simulator) {
  const sim::SimConfig& c = simulator.config();
  const int planned = c.plannedRevisits(), driven = sim::drivenRevisits(simulator);
  if (driven >= planned) return;
  std::cerr << "warning: only " << driven << " of the " << planned << " planned revisit" << (planned == 1 ? "" : "s")
            << " fit in " << c.frames << " frames";
  const int needed = sim::framesForRevisits(c);
  if (needed > 0) std::cerr << "; --frames " << needed << " would hold " << (planned == 1 ? "it" : "them all");
  std::cerr << (driven == 0 ? " (without a revisit the sequence has no loops to find)" : "") << "\n";
}

/// A second session's first session: its manifest, checked against its poses.txt once the world is rebuilt.
std::shared_ptr<const sim::SimConfig> firstSession(const SimulateOptions& o) {
  if (o.world_of.empty()) return nullptr;
  std::error_code ec;
  if (fs::equivalent(o.out, o.world_of, ec)) {
    throw Error("--out " + o.out + " is the first session's folder: a second session goes into a folder of its own");
  }
  auto first = std::make_shared<sim::SimConfig>(sim::readManifest(o.world_of));
  if (first->world_of) {
    throw Error(o.world_of + " is itself a second session (of seed " + std::to_string(first->world_of->seed) +
                "); pass its first session instead: every session of a world shares that one's frame");
  }
  if (o.scene_given && sim::parseSceneKind(o.scene) != first->scene) {
    throw Error("--scene " + o.scene + ": " + o.world_of + " was simulated in the " + sim::sceneName(first->scene) +
                " scene");
  }
  return first;
}

/// Refuses a first session whose poses.txt the rebuilt world does not reproduce (another simulator version).
void checkFirstSession(const sim::Simulator& s, const std::string& dir) {
  const std::vector<Eigen::Matrix4d> written = sim::readBackLidarPoses(dir);
  const std::vector<Eigen::Matrix4d>& rebuilt = s.firstSessionPoses();
  const Eigen::Matrix4d to0 = s.T_world_origin().inverse();
  double worst = 0.0;
  for (size_t i = 0; i < std::min(written.size(), rebuilt.size()); ++i) {
    worst = std::max(worst, (written[i].topRightCorner<3, 1>() - (to0 * rebuilt[i]).topRightCorner<3, 1>()).norm());
  }
  if (written.size() != rebuilt.size() || worst > 1e-3) {
    throw Error(dir + "/poses.txt does not match the world rebuilt from its " + sim::kManifestName + " (" +
                std::to_string(written.size()) + " poses, " + std::to_string(rebuilt.size()) + " rebuilt, up to " +
                fixed(worst, 3) + " m apart): it was written by another version of the simulator, or edited");
  }
}

void simulate(const SimulateOptions& o) {
  sim::SimConfig config;
  config.world_of = firstSession(o);
  config.follow = o.follow;
  config.frames = o.frames;
  // A second session's default seed: the next one after its first session's.
  config.seed = o.seed_given || !config.world_of ? o.seed : config.world_of->seed + 1;
  config.scene = config.world_of ? config.world_of->scene : sim::parseSceneKind(o.scene);
  config.sensor = sim::SensorConfig::preset(sim::parseSensorKind(o.sensor));
  config.accumulate = o.accumulate;
  config.label_noise = o.label_noise;
  config.revisits = o.revisits;
  sim::checkOutputDir(o.out, o.force);  // before building the world; writeSequence checks again
  const auto start = std::chrono::steady_clock::now();
  const sim::Simulator simulator(config);
  if (config.world_of) checkFirstSession(simulator, o.world_of);
  warnIfRevisitsDoNotFit(simulator);
  sim::WriteOptions w;
  w.dir = o.out;
  w.threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  w.force = o.force;
  w.previews = !o.no_preview;
  w.odometry = sim::OdometryNoise::scaled(o.odometry_drift);
  Progress progress("frames", static_cast<size_t>(config.frames));
  const sim::SequenceStats stats =
      sim::writeSequence(simulator, w, [&](int done) { progress.update(static_cast<size_t>(done), ""); });
  progress.finish();
  const bool nuscenes = sim::parseLabelSpace(o.label_space) == sim::LabelSpace::kNuScenes;
  if (nuscenes) sim::rewriteLabelsAsNuScenes(o.out, stats.frames);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  printSummary(simulator, stats, o.out, seconds);
  if (nuscenes) {
    std::cout << "labels/: nuScenes-lidarseg ids, one byte a point (the shares above are of the simulator's classes); "
                 "read them with --config configs/nuscenes.yaml\n";
  }
  // --force never deletes: frames of an earlier, longer run stay and would be read as part of this sequence.
  size_t stale = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(o.out) / "velodyne")) {
    const std::string stem = entry.path().stem().string();
    const bool digits =
        std::all_of(stem.begin(), stem.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
    const bool ours = stem.size() == 6 && digits && std::stoi(stem) < stats.frames;
    if (entry.path().extension() == ".bin" && !ours) ++stale;
  }
  if (stale > 0) {
    std::cerr << "warning: " << o.out << "/velodyne holds " << stale
              << " other .bin files (not written by this run); readers of the folder will take them as frames\n";
  }
}

}  // namespace

void addSimulateCommand(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand("simulate", "Write a simulated semantic LiDAR sequence with revisits "
                                                 "(SemanticKITTI layout, ground-truth poses and loop pairs)");
  cmd->add_option("--out", o->out, "output folder (new or empty; see --force)")->required();
  cmd->add_option("--frames", o->frames, "frames to simulate (10 Hz); disk: about 2.5 MB a frame (hdl64), "
                  "0.6 MB (hdl32), so 2,000 hdl64 frames take 5 GB")->required()->check(CLI::Range(1, 1000000));
  cmd->add_option("--seed", o->seed, "random seed: the same seed gives the same files (required without "
                                     "--world-of; with it, the first session's seed + 1 by default)");
  cmd->add_option("--world-of", o->world_of,
                  "a second session through the world of this earlier simulated sequence (its streets and "
                  "buildings; new traffic, route and noise), with poses in its frame; writes cross_session.txt")
      ->check(CLI::ExistingDirectory);
  cmd->add_flag("--follow", o->follow,
                "with --world-of: drive only the first session's roads, either way (the same streets again: no new "
                "road), e.g. for merging many drives into one map");
  cmd->add_option("--scene", o->scene, "world preset (with --world-of: the first session's)")
      ->check(CLI::IsMember({"urban", "suburban", "rural"}))
      ->capture_default_str();
  cmd->add_option("--sensor", o->sensor,
                  "LiDAR: Velodyne HDL-64E, HDL-32E (32 beams +10.67..-30.67 deg, 70 m, ~35k rays a turn, as "
                  "nuScenes) or Livox Mid-70")
      ->check(CLI::IsMember({"hdl64", "hdl32", "mid70"}))
      ->capture_default_str();
  cmd->add_option("--label-space", o->label_space,
                  "ids of labels/: SemanticKITTI raw ids (uint32) or nuScenes-lidarseg's (one byte a point; building, "
                  "pole and sign 28, vegetation and trunk 30, terrain 27, fence 9, road 24, car 17, ...)")
      ->check(CLI::IsMember({"semantickitti", "nuscenes"}))
      ->capture_default_str();
  cmd->add_option("--accumulate", o->accumulate,
                  "raw scans merged into each frame (default: hdl64 and hdl32 1, mid70 10); `--sensor mid70 "
                  "--accumulate 1` writes the raw scans, for `run|eval --accumulate N`")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--label-noise", o->label_noise,
                  "segmentation error rate R: 0 = ground truth; the default is like RangeNet++")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--revisits", o->revisits, "planned revisits (default: one per 500 frames)")
      ->check(CLI::Range(0, 10000));
  cmd->add_option("--odometry-drift", o->odometry_drift,
                  "noise of odometry.txt as a multiple of the default model (about 2 % drift at 1 km); "
                  "0 = the true motion, up to rounding")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "worker threads (default: all cores); the output does not depend on it")
      ->check(CLI::Range(1, kMaxThreads));
  cmd->add_flag("--force", o->force, "write into a non-empty folder, overwriting only the simulator's own files");
  cmd->add_flag("--no-preview", o->no_preview, "skip preview_scan.png and preview_trajectory.png");
  cmd->callback([o, cmd] {
    o->seed_given = cmd->count("--seed") > 0;
    o->scene_given = cmd->count("--scene") > 0;
    // Command-line mistakes, before any file is read: CLI11's errors, so they exit with the usage code.
    if (o->world_of.empty() && !o->seed_given) throw CLI::RequiredError("--seed (needed without --world-of)");
    if (o->follow && o->world_of.empty()) throw CLI::ValidationError("--follow", "follows the roads of --world-of");
    if (!o->world_of.empty() && cmd->count("--revisits") > 0) {
      throw CLI::ValidationError("--revisits", "a second session (--world-of) plans no revisits of its own");
    }
    simulate(*o);
  });
}

}  // namespace sgtllc::cli
