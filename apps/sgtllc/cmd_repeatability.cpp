// `sgtllc repeatability SEQ_DIR`: do a place's nodes come back in another scan of it, with the folder's labels and
// with the geometric labeller, and how far do the geometric labels agree with the folder's (docs/labeller.md §5).
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "commands.h"
#include "common.h"
#include "sgtllc/eval/label_agreement.h"
#include "sgtllc/eval/node_repeatability.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/io/sequence.h"
#include "sgtllc/label/geometric_labeller.h"
#include "sgtllc/node_extraction.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {
namespace {

struct RepeatabilityCliOptions {
  std::string sequence, labels_dir, poses, calib, config;
  std::vector<std::string> pairs;  ///< "Q:M" frame names
  int gap = 1;
  double max_distance = 20.0;
  eval::RepeatabilityOptions measure;
  bool json = false;
};

/// One scan of the folder reduced both ways: nodes from its labels and from the geometric labeller.
struct ScanNodes {
  std::vector<Node> file, geometric;
};

struct PairResult {
  std::string query, match;
  double distance = 0.0;
  eval::NodeRepeatability file, geometric;
};

/// LiDAR poses by frame number: the poses file through the calib's Tr when there is one (KITTI's cam0 poses),
/// else as written (LiDAR poses, as nuScenes' conversion and KISS-ICP write them).
std::vector<Eigen::Matrix4d> lidarPosesOf(const RepeatabilityCliOptions& o, std::string* described) {
  const std::string poses = o.poses.empty() ? (fs::path(o.sequence) / "poses.txt").string() : o.poses;
  std::string calib = o.calib;
  if (calib.empty() && fs::is_regular_file(fs::path(o.sequence) / "calib.txt")) {
    calib = (fs::path(o.sequence) / "calib.txt").string();
  }
  const std::vector<Eigen::Matrix4d> file = io::readKittiPoses(poses);
  *described = calib.empty() ? poses + " (LiDAR poses: no calib)" : poses + " through " + calib;
  return calib.empty() ? file : io::lidarPoses(file, io::readKittiCalibTr(calib));
}

long frameNumber(const std::string& name, const std::string& dir) {
  char* end = nullptr;
  const long n = std::strtol(name.c_str(), &end, 10);
  if (name.empty() || *end != '\0' || n < 0) {
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
  Config geometric_config = config;
  geometric_config.labeller.source = LabelSource::kGeometric;
  const io::SequenceDir seq(o.sequence, io::SequenceLabels{true, o.labels_dir});
  std::string poses_from;
  const std::vector<Eigen::Matrix4d> poses = lidarPosesOf(o, &poses_from);
  const auto pairs = pairIndices(o, seq);

  const NodeExtractor from_file(config.cluster, config.labels, config.graph.max_nodes);
  const NodeExtractor from_geometry(config.cluster, effectiveLabelConfig(geometric_config), config.graph.max_nodes);
  const label::GeometricLabeller labeller(config.labeller);
  const LabelMap reference_map(config.labels);
  const eval::ClassMerge merge = eval::labellerMerge(config.labels);

  // Each scan is reduced once, when a pair first needs it; the label agreement is summed over those scans.
  std::map<size_t, ScanNodes> scans;
  eval::ClassAgreement agreement;
  const auto nodesOf = [&](size_t i) -> const ScanNodes& {
    auto it = scans.find(i);
    if (it != scans.end()) return it->second;
    const LabeledCloud cloud = seq.load(i);
    ScanNodes s;
    s.file = from_file.extract(cloud).nodes;
    const label::Labelling l = labeller.classify(cloud.points);
    agreement.add(l.classes, eval::stableClasses(cloud.labels, reference_map), merge);
    s.geometric = from_geometry.extract(label::labelCloud(cloud.points, labeller)).nodes;
    return scans.emplace(i, std::move(s)).first->second;
  };

  std::vector<PairResult> results;
  eval::NodeRepeatability file_all, geometric_all;
  size_t skipped = 0;
  for (const auto& [q, m] : pairs) {
    const long nq = frameNumber(seq.frameName(q), o.sequence), nm = frameNumber(seq.frameName(m), o.sequence);
    if (static_cast<size_t>(std::max(nq, nm)) >= poses.size()) {
      throw Error(poses_from + ": no pose for frame " + std::to_string(std::max(nq, nm)) + " (" +
                  std::to_string(poses.size()) + " poses)");
    }
    const Eigen::Isometry3d T_m_q(poses[nm].inverse() * poses[nq]);
    PairResult r{seq.frameName(q), seq.frameName(m), T_m_q.translation().norm(), {}, {}};
    if (r.distance > o.max_distance) {
      ++skipped;
      continue;
    }
    const ScanNodes& a = nodesOf(q);
    const ScanNodes& b = nodesOf(m);
    r.file = eval::nodeRepeatability(a.file, b.file, T_m_q, o.measure);
    r.geometric = eval::nodeRepeatability(a.geometric, b.geometric, T_m_q, o.measure);
    file_all.add(r.file);
    geometric_all.add(r.geometric);
    results.push_back(r);
  }
  if (results.empty()) {
    throw Error(o.sequence + ": no pair within --max-distance " + fixed(o.max_distance, 1) + " m (" +
                std::to_string(skipped) + " farther apart)");
  }
  const LabelConfig geometric_labels = effectiveLabelConfig(geometric_config);

  if (o.json) {
    Json j = {{"sequence", o.sequence}, {"poses", poses_from}, {"radius_m", o.measure.radius},
              {"range_m", o.measure.range}, {"pairs_skipped", skipped},
              {"file", countsJson(file_all, config.labels)},
              {"geometric", countsJson(geometric_all, geometric_labels)}};
    Json per_pair = Json::array();
    for (const PairResult& r : results) {
      per_pair.push_back({{"query", r.query}, {"match", r.match}, {"distance_m", r.distance},
                          {"file", countsJson(r.file, config.labels)},
                          {"geometric", countsJson(r.geometric, geometric_labels)}});
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
  printCounts("labels (file)", file_all, config.labels);
  printCounts("geometric labeller", geometric_all, geometric_labels);
  for (const PairResult& r : results) {
    std::printf("  %s -> %s  %6.2f m   file %.3f (%d/%d)   geometric %.3f (%d/%d)\n",
                io::escapeContent(r.query).c_str(), io::escapeContent(r.match).c_str(), r.distance, r.file.share(),
                r.file.totalRepeated(), r.file.totalNodes(), r.geometric.share(), r.geometric.totalRepeated(),
                r.geometric.totalNodes());
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
                  "calib.txt whose Tr takes cam0 poses to the LiDAR frame (default SEQ_DIR/calib.txt if it exists; "
                  "without one the poses are LiDAR poses)");
  cmd->add_option("--pair", o->pairs, "QUERY:MATCH scan names to compare (repeatable; default: each scan with the --gap-th next)");
  cmd->add_option("--gap", o->gap, "compare each scan with the one this many scans after it")->check(CLI::Range(1, 1000000));
  cmd->add_option("--max-distance", o->max_distance, "skip pairs whose sensors are farther apart (m)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--radius", o->measure.radius, "a node repeats if a same-class node is this close (m)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--range", o->measure.range, "count nodes within this horizontal distance of both sensors (m; 0 = all)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--config", o->config, "YAML configuration (see `sgtllc config`)");
  cmd->add_flag("--json", o->json, "print one JSON object");
  cmd->callback([o] { runRepeatability(*o); });
}

}  // namespace sgtllc::cli
