// The settings of the labels, clustering, graph, descriptors, retrieval and association (config.h documents the
// fields and cites the algorithm's sections).
#include "config_ranges.h"
#include "setting_table.h"

namespace sgtllc::detail {

void addLabelSettings(std::vector<Setting>* out) {
  SectionTable<LabelConfig> l("labels", [](Config& c) -> LabelConfig& { return c.labels; }, out);
  l.choice("preset", &LabelConfig::preset,
           {{"semantickitti", LabelPreset::kSemanticKittiRaw},
            {"semantickitti_learning", LabelPreset::kSemanticKittiLearning},
            {"mulran", LabelPreset::kMulRan},
            {"mcd", LabelPreset::kMcd},
            {"nuscenes", LabelPreset::kNuScenes},
            {"custom", LabelPreset::kCustom}},
           "id convention of the input labels (algorithm §1, §8)");
  l.choice("format", &LabelConfig::format,
           {{"auto", LabelFormat::kAuto}, {"uint32", LabelFormat::kUint32}, {"uint8", LabelFormat::kUint8}},
           "label files: 4 bytes (uint32) or 1 byte (uint8) a point; auto tells them by size");
  l.custom("custom_map",
           "raw id: class index 0..C-1 (building … traffic-sign, then extra classes) or -1 (known, dropped); "
           "used with preset custom");
  l.custom("extra_classes",
           "classes 7, 8, … beyond the seven, each {name, ids} with its own cluster.NAME; at most 16 classes C in all "
           "(local descriptor C²×3, G1/G3 2·C², G2 C³)");
}

void addClusterSettings(const LabelConfig& labels, std::vector<Setting>* out) {
  for (int k = 0; k < labels.numClasses(); ++k) {
    SectionTable<ClassClusterConfig> c("cluster." + labels.className(k),
                                       [k](Config& config) -> ClassClusterConfig& { return config.cluster.classes.at(k); },
                                       out);
    // The lower bound keeps the voxel cells of points within ±kMaxCoordinate exact integers.
    c.number("voxel", &ClassClusterConfig::voxel, "0 (no downsampling) or [0.001, 10]", "m", "voxel leaf");
    c.number("radius", &ClassClusterConfig::radius, "[0.001, 10]", "m", "FEC radius r");
    c.number("min_size", &ClassClusterConfig::min_size, "[1, 1000000]", "",
             "minimum cluster size (voxels if voxel > 0, else points)");
    c.choice("centre_height", &ClassClusterConfig::centre_height,
             {{"points", CentreHeight::kPoints}, {"sensor", CentreHeight::kSensor}},
             "node centre's height: its points' mean, or the sensor's (z = 0; upright objects)");
    c.flag("score_unmatched", &ClassClusterConfig::score_unmatched,
           "unmatched nodes count in the loop score's node count (false: only matched ones do)");
  }
  SectionTable<ClusterConfig> c("cluster", [](Config& config) -> ClusterConfig& { return config.cluster; }, out);
  c.number("max_neighbors", &ClusterConfig::max_neighbors, "[1, 10000]", "",
           "FEC neighbour cap per radius query, seed included");
  c.number("duplicate_radius", &ClusterConfig::duplicate_radius, "[0, 100]", "m",
           "skip a cluster this close to an accepted same-class centre");
  c.choice("centre", &ClusterConfig::centre, {{"points", CentreSource::kPoints}, {"voxels", CentreSource::kVoxels}},
           "node centre: mean of original points or of voxel centroids");
}

void addStageSettings(std::vector<Setting>* out) {
  const std::string frames = "[1, " + std::to_string(kMaxFrames) + "]";
  const std::string nodes = "[1, " + std::to_string(kMaxGraphNodes) + "]";
  SectionTable<GraphConfig> g("graph", [](Config& c) -> GraphConfig& { return c.graph; }, out);
  g.number("sigma_d", &GraphConfig::sigma_d, "(0, 1000]", "m", "σ_d: edge iff centre distance < σ_d");
  g.number("max_nodes", &GraphConfig::max_nodes, nodes, "", "most nodes per frame (a scan keeps its largest clusters)");
  g.flag("allow_k_equals_i", &GraphConfig::allow_k_equals_i, "allow the path i→j→i (authors' code)");

  SectionTable<DescriptorConfig> d("descriptor", [](Config& c) -> DescriptorConfig& { return c.descriptor; }, out);
  d.choice("kind", &DescriptorConfig::kind,
           {{"dot", SubVectorKind::kDotProducts}, {"angle", SubVectorKind::kAngles}, {"length", SubVectorKind::kLengths}},
           "slot entries: dot products, angles only, lengths only");
  d.choice("order", &DescriptorConfig::order, {{"paper", SubVectorOrder::kPaper}, {"code", SubVectorOrder::kCode}},
           "sub-vector entries: (a_i,a_j,a_k) or (a_i,a_k,-a_j)");
  d.choice("global_mode", &DescriptorConfig::global_mode,
           {{"G1", GlobalMode::kG1}, {"G2", GlobalMode::kG2}, {"G3", GlobalMode::kG3}},
           "global descriptor (algorithm §5)");

  SectionTable<RetrievalConfig> r("retrieval", [](Config& c) -> RetrievalConfig& { return c.retrieval; }, out);
  r.choice("key", &RetrievalConfig::key,
           {{"histogram", RetrievalKey::kDistanceHistogram}, {"global", RetrievalKey::kGlobalDescriptor}},
           "stored, searched key: class-pair distance histogram or Des^G");
  r.number("histogram_bins", &RetrievalConfig::histogram_bins, "[1, 100]", "", "distance-histogram bins per class pair");
  r.number("histogram_range", &RetrievalConfig::histogram_range, "(0, 1000]", "m", "distances the histogram covers");
  r.number("num_candidates", &RetrievalConfig::num_candidates, "[1, 1000]", "", "K: candidates retrieved per query");
  // A frame never matches itself: G ≥ 1.
  r.number("exclude_recent", &RetrievalConfig::exclude_recent, frames, "", "G: query q searches frames <= q - G");
  r.number("warmup_frames", &RetrievalConfig::warmup_frames, "[0, " + std::to_string(kMaxFrames) + "]", "",
           "no query before this many frames (authors' code: 150)");
  r.choice("method", &RetrievalConfig::method,
           {{"brute_force", RetrievalMethod::kBruteForce},
            {"kdtree", RetrievalMethod::kKdTree},
            {"ivf", RetrievalMethod::kIvf}},
           "nearest-neighbour search");
  r.number("ivf_lists", &RetrievalConfig::ivf_lists, "[0, 65536]", "", "inverted-file lists (method ivf); 0: 2 sqrt(N)");
  r.number("ivf_probe", &RetrievalConfig::ivf_probe, "[1, 65536]", "", "inverted-file lists scanned per query (method ivf)");
  r.number("ivf_train_frames", &RetrievalConfig::ivf_train_frames, "[64, " + std::to_string(kMaxFrames) + "]", "",
           "frames stored before the inverted file is trained");

  SectionTable<AssociationConfig> a("association", [](Config& c) -> AssociationConfig& { return c.association; },
                                    out);
  a.number("sigma_1", &AssociationConfig::sigma_1, "[-1, 1]", "", "σ_1: a slot matches iff cos(u, v) > σ_1");
  a.number("max_delta_aj", &AssociationConfig::max_delta_aj, "(0, 1000000]", "m²", "... and |Δa_j| < this");
  a.ruledNumber("sigma_2", &AssociationConfig::sigma_2, "[0, 1] with score ratio, [0, C²] with score count", "",
                "σ_2: accept the best node pair iff S >= σ_2");
  a.choice("score", &AssociationConfig::score, {{"ratio", NodeScore::kRatio}, {"count", NodeScore::kCount}},
           "node similarity S");
  a.custom("entries", "sub-vector entries compared, by vertex: any of i, j, k (ablation)");
}

}  // namespace sgtllc::detail
