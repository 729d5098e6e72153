// `sgtllc repeatability SEQ_DIR`: do a place's nodes come back in another scan of it, with the folder's labels and
// with the geometric labeller, and how far do the geometric labels agree with the folder's (docs/labeller.md §5).
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "commands.h"
#include "common.h"
#include "loop_closing.h"
#include "sgtllc/eval/label_agreement.h"
#include "sgtllc/eval/node_repeatability.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/io/sequence.h"
#include "sgtllc/label/cloud_labeller.h"
#include "sgtllc/node_extraction.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {
namespace {

struct RepeatabilityCliOptions {
  std::string sequence, labels_dir, poses, calib, config;
  io::PoseFrame pose_frame = io::PoseFrame::kAuto;
  std::vector<std::string> pairs;  ///< "Q:M" frame names
  int gap = 1;
  double max_distance = 20.0;
  eval::RepeatabilityOptions measure;
  bool json = false;
};

/// One way of labelling the scans: the folder's labels, the hybrid (when the label set lacks poles or trunks)
/// and the geometric labeller.
struct Way {
  const char* name;  ///< printed
  const char* key;   ///< JSON
  label::CloudLabeller labeller;
  NodeExtractor extractor;
};

struct PairResult {
  std::string query, match;
  double distance = 0.0;
  std::vector<eval::NodeRepeatability> ways;  ///< one per Way
};

/// LiDAR poses by frame number: the poses file (KITTI or TUM) read by the pose-frame rule, through --calib or
/// SEQ_DIR/calib.txt when there is one (io/trajectory_frame.h).
std::vector<Eigen::Isometry3d> lidarPosesOf(const RepeatabilityCliOptions& o, std::string* described) {
  const std::string poses = o.poses.empty() ? (fs::path(o.sequence) / "poses.txt").string() : o.poses;
  const std::string calib = o.pose_frame == io::PoseFrame::kLidar ? o.calib : sequenceCalib(o.calib, o.sequence);
  Odometry read = readOdometry(poses, calib, o.pose_frame, 0);
  *described = poses + (read.trajectory.calib_Tr ? " through " + calib : std::string(" (LiDAR poses)"));
  return std::move(read.poses);
}

long frameNumber(const std::string& name, const std::string& dir) {
  char* end = nullptr;
  const long n = std::strtol(name.c_str(), &end, 10);
  if (name.empty() || !std::isdigit(static_cast<unsigned char>(name[0])) || *end != '\0') {
    throw Error(dir + ": scan " + io::quoteContent(name) + " is not named by its frame number (the line of poses.txt)");
  }
  return n;
}

/// The pairs to measure, as indices into the folder: --pair Q:M, else each scan with the one --gap after it.
std::vector<std::pair<size_t, size_t>> pairIndices(const RepeatabilityCliOptions& o, const io::SequenceDir& seq) {
  std::vector<std::pair<size_t, size_t>> out;
  if (o.pairs.empty()) {
    for (size_t i = 0; i + static_cast<size_t>(o.gap) < seq.size(); ++i) out.emplace_back(i, i + o.gap);
    return out;
  }
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < seq.size(); ++i) index[seq.frameName(i)] = i;
  for (const std::string& p : o.pairs) {
    const size_t colon = p.find(':');
    const std::string q = p.substr(0, colon), m = colon == std::string::npos ? "" : p.substr(colon + 1);
    if (!index.count(q) || !index.count(m)) {
      throw Error("--pair " + io::quoteContent(p) + ": expected QUERY:MATCH, two scan names of " + o.sequence +
                  "/velodyne (e.g. 004501:000052)");
    }
    out.emplace_back(index[q], index[m]);
  }
  return out;
}

void printCounts(const char* title, const eval::NodeRepeatability& r, const LabelConfig& labels) {
  std::printf("  %-26s %.3f (%d of %d)", title, r.share(), r.totalRepeated(), r.totalNodes());
  for (int c = 0; c < labels.numClasses(); ++c) {
    if (r.nodes[c] > 0) std::printf("  %s %d/%d", labels.className(c).c_str(), r.repeated[c], r.nodes[c]);
  }
  std::printf("\n");
}

Json countsJson(const eval::NodeRepeatability& r, const LabelConfig& labels) {
  Json per_class = Json::object();
  for (int c = 0; c < labels.numClasses(); ++c) {
    if (r.nodes[c] == 0) continue;
    per_class[labels.className(c)] = {{"nodes", r.nodes[c]}, {"repeated", r.repeated[c]},
                                      {"other_class", r.other_class[c]}, {"share", r.share(c)}};
  }
  return {{"share", r.share()}, {"nodes", r.totalNodes()}, {"repeated", r.totalRepeated()}, {"classes", per_class}};
}

void runRepeatability(const RepeatabilityCliOptions& o) {
  const Config config = loadConfigOption(o.config, 0);
  // With --pair only the named scans need labels (a KITTI folder may label a few of its scans).
  const io::SequenceDir seq(o.sequence, io::SequenceLabels{true, o.labels_dir, config.labels.format, o.pairs.empty()});
  std::string poses_from;
  const std::vector<Eigen::Isometry3d> poses = lidarPosesOf(o, &poses_from);
  const auto pairs = pairIndices(o, seq);

  std::vector<Way> ways;
  const auto addWay = [&](const char* name, const char* key, LabelSource source) {
    Config c = config;
    c.labeller.source = source;
    ways.push_back({name, key, label::CloudLabeller(c.labels, c.labeller),
                    NodeExtractor(c.cluster, effectiveLabelConfig(c), c.graph.max_nodes)});
  };
  addWay("labels (file)", "file", LabelSource::kFile);
  if (hybridSplits(config.labels).any()) addWay("hybrid", "hybrid", LabelSource::kHybrid);
  addWay("geometric labeller", "geometric", LabelSource::kGeometric);
  const label::GeometricLabeller labeller(config.labeller);
  const LabelMap reference_map(config.labels);
  const eval::ClassMerge merge = eval::labellerMerge(config.labels);

  // Each scan is reduced once, when a pair first needs it; the label agreement is summed over those scans.
  std::map<size_t, std::vector<std::vector<Node>>> scans;  // per scan, the nodes of each way
  eval::ClassAgreement agreement;
  const auto nodesOf = [&](size_t i) -> const std::vector<std::vector<Node>>& {
    auto it = scans.find(i);
    if (it != scans.end()) return it->second;
    const LabeledCloud cloud = seq.load(i);
    const label::Labelling shapes = labeller.classify(cloud.points);  // once, for every way and the agreement
    std::vector<std::vector<Node>> nodes;
    for (const Way& w : ways) {
      nodes.push_back(w.extractor.extract(w.labeller.changesLabels() ? w.labeller.apply(cloud, shapes) : cloud).nodes);
    }
    agreement.add(shapes.classes, eval::stableClasses(cloud.labels, reference_map), merge);
    return scans.emplace(i, std::move(nodes)).first->second;
  };

  std::vector<PairResult> results;
  std::vector<eval::NodeRepeatability> all(ways.size());
  size_t skipped = 0;
  for (const auto& [q, m] : pairs) {
    const long nq = frameNumber(seq.frameName(q), o.sequence), nm = frameNumber(seq.frameName(m), o.sequence);
    if (static_cast<size_t>(std::max(nq, nm)) >= poses.size()) {
      throw Error(poses_from + ": no pose for frame " + std::to_string(std::max(nq, nm)) + " (" +
                  std::to_string(poses.size()) + " poses)");
    }
    const Eigen::Isometry3d T_m_q = poses[nm].inverse() * poses[nq];
    PairResult r{seq.frameName(q), seq.frameName(m), T_m_q.translation().norm(), {}};
    if (r.distance > o.max_distance) {
      ++skipped;
      continue;
    }
    const auto& a = nodesOf(q);
    const auto& b = nodesOf(m);
    for (size_t w = 0; w < ways.size(); ++w) {
      r.ways.push_back(eval::nodeRepeatability(a[w], b[w], T_m_q, o.measure));
      all[w].add(r.ways.back());
    }
    results.push_back(std::move(r));
  }
  if (results.empty()) {
    throw Error(o.sequence + ": no pair within --max-distance " + fixed(o.max_distance, 1) + " m (" +
                std::to_string(skipped) + " farther apart)");
  }

  if (o.json) {
    Json j = {{"sequence", o.sequence}, {"poses", poses_from}, {"radius_m", o.measure.radius},
              {"range_m", o.measure.range}, {"pairs_skipped", skipped}};
    for (size_t w = 0; w < ways.size(); ++w) j[ways[w].key] = countsJson(all[w], ways[w].labeller.nodeLabels());
    Json per_pair = Json::array();
    for (const PairResult& r : results) {
      Json p = {{"query", r.query}, {"match", r.match}, {"distance_m", r.distance}};
      for (size_t w = 0; w < ways.size(); ++w) p[ways[w].key] = countsJson(r.ways[w], ways[w].labeller.nodeLabels());
      per_pair.push_back(p);
    }
    j["pairs"] = per_pair;
    Json classes = Json::object();
    for (int c = 0; c < config.labels.numClasses(); ++c) {
      if (merge[c] != c || (agreement.referencePoints(c) == 0 && agreement.fp[c] == 0)) continue;
      classes[config.labels.className(c)] = {{"precision", agreement.precision(c)}, {"recall", agreement.recall(c)},
                                             {"iou", agreement.iou(c)},
                                             {"reference_points", agreement.referencePoints(c)}};
    }
    j["label_agreement"] = {{"scans", scans.size()}, {"classes", classes}};
    std::cout << jsonText(j) << "\n";
    return;
  }
  std::cout << o.sequence << ": " << results.size() << " pairs (" << skipped << " beyond " << fixed(o.max_distance, 1)
            << " m skipped), " << scans.size() << " scans; poses " << poses_from << "\n";
  std::cout << "node repeatability: share of both scans' nodes with a same-class node of the other within "
            << fixed(o.measure.radius, 2) << " m, nodes within " << fixed(o.measure.range, 0)
            << " m of both sensors\n";
  for (size_t w = 0; w < ways.size(); ++w) printCounts(ways[w].name, all[w], ways[w].labeller.nodeLabels());
  for (const PairResult& r : results) {
    std::printf("  %s -> %s  %6.2f m", io::escapeContent(r.query, io::kNameBytes).c_str(),
                io::escapeContent(r.match, io::kNameBytes).c_str(),
                r.distance);
    for (size_t w = 0; w < ways.size(); ++w) {
      std::printf("   %s %.3f (%d/%d)", ways[w].key, r.ways[w].share(), r.ways[w].totalRepeated(),
                  r.ways[w].totalNodes());
    }
    std::printf("\n");
  }
  std::printf("label agreement of the geometric labeller with the labels, %zu scans (precision / recall / IoU, "
              "reference points):\n", scans.size());
  for (int c = 0; c < config.labels.numClasses(); ++c) {
    if (merge[c] != c || (agreement.referencePoints(c) == 0 && agreement.fp[c] == 0)) continue;
    std::string name = config.labels.className(c);
    for (int from = 0; from < config.labels.numClasses(); ++from) {
      if (from != c && merge[from] == c) name += "+" + config.labels.className(from);
    }
    std::printf("  %-28s %.3f / %.3f / %.3f  %llu\n", name.c_str(), agreement.precision(c), agreement.recall(c),
                agreement.iou(c), static_cast<unsigned long long>(agreement.referencePoints(c)));
  }
}

}  // namespace

void addRepeatabilityCommand(CLI::App& app) {
  auto o = std::make_shared<RepeatabilityCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "repeatability", "Node repeatability between scans of one place (labels and geometric labeller), label agreement");
  cmd->add_option("SEQ_DIR", o->sequence, "sequence folder: velodyne/, labels/, poses.txt (+ calib.txt for cam0 poses)")
      ->required();
  cmd->add_option("--labels-dir", o->labels_dir, "read NAME.label files from this folder instead of SEQ_DIR/labels");
  cmd->add_option("--poses", o->poses, "poses file (default SEQ_DIR/poses.txt; line i = frame i)");
  cmd->add_option("--calib", o->calib,
                  "calib.txt whose Tr takes cam0 poses to the LiDAR frame (default SEQ_DIR/calib.txt if it exists)");
  addPoseFrameOption(*cmd, o->pose_frame, "the poses file");
  cmd->add_option("--pair", o->pairs,
                  "QUERY:MATCH scan names to compare (repeatable; default: each scan with the --gap-th next); only "
                  "these scans need labels");
  cmd->add_option("--gap", o->gap, "compare each scan with the one this many scans after it")->check(CLI::Range(1, 1000000));
  cmd->add_option("--max-distance", o->max_distance, "skip pairs whose sensors are farther apart (m)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--radius", o->measure.radius, "a node repeats if a same-class node is this close (m)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--range", o->measure.range, "count nodes within this horizontal distance of both sensors (m; 0 = all)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`)");
  cmd->add_flag("--json", o->json, "print one JSON object");
  cmd->callback([o] {
    checkPoseFrameOptions("repeatability", o->calib, o->pose_frame, false);
    runRepeatability(*o);
  });
}

}  // namespace sgtllc::cli
