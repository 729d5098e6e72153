/// @file config.h
/// @brief The one configuration aggregate. Every field has a default, units and the paper symbol or algorithm section (docs/algorithm.md).
///
/// Defaults are the project's choices for KITTI (algorithm §1–§8). YAML keys mirror the field names one to one
/// (`cluster.building.min_size`, `verification.sigma_4`, …); `sgtllc config` prints them.
///
/// Each setting's key, range, unit and one line of meaning are declared once, in the settings table
/// (sgtllc/config/settings.h, src/config/settings_*.cpp; listed in docs/configuration.md), which drives
/// Config::validate(), the YAML reader and writer and the Python properties. Scores and fractions lie in [0, 1],
/// cosines in [-1, 1]; lengths are bounded by what a LiDAR scan can contain; counts and iterations are bounded so
/// that no configuration can make a single frame take more than seconds. The comments below say what each field
/// does and why it has its default.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sgtllc/config/backend_config.h"
#include "sgtllc/config/labeller_config.h"
#include "sgtllc/config/registration_config.h"
#include "sgtllc/config/verification_config.h"
#include "sgtllc/types.h"

namespace sgtllc {

/// How raw per-point ids map to the stable classes (algorithm §1, §8).
enum class LabelPreset {
  kSemanticKittiRaw,       ///< SemanticKITTI raw ids (50 building … 81 traffic-sign); low 16 bits of the .label word
  kSemanticKittiLearning,  ///< SemanticKITTI learning ("train") ids 13..19
  kMulRan,                 ///< MulRan: train id = label + 1
  kMcd,                    ///< MCD: the authors' 29-entry map
  kCustom,                 ///< LabelConfig::custom_map only
  kNuScenes,               ///< nuScenes-lidarseg's 32 classes (+ moving 32..39): manmade, barrier, vegetation, terrain
};

/// How a label file stores its ids (the readers in sgtllc/io; the core never opens files).
enum class LabelFormat {
  kAuto,    ///< from the file size: 4·N bytes → uint32, N bytes → uint8 (N = the scan's point count)
  kUint32,  ///< one little-endian uint32 per point (SemanticKITTI .label)
  kUint8,   ///< one byte per point (nuScenes-lidarseg .bin and its KITTI-layout conversions)
};

/// A class beyond the paper's seven (e.g. vehicle), declared by the configuration. It becomes class index
/// 7 + its position in LabelConfig::extra_classes and clusters with its own ClassClusterConfig.
struct ExtraClass {
  /// Lower-case name, as in `cluster.NAME` and in printed results: letters a–z, digits, '-' and '_', starting with
  /// a letter; unique and not one of the paper's seven.
  std::string name;
  /// Raw ids (in the convention of LabelConfig::preset, 0..65535) that map to this class, each listed once and
  /// none a stable id of the preset (a SemanticKITTI id such as car = 10 is in the label space but dropped by the
  /// preset, so it may be claimed). May be empty only with preset custom, where custom_map can target the class.
  std::vector<uint32_t> ids;

  bool operator==(const ExtraClass& o) const { return name == o.name && ids == o.ids; }
};

struct LabelConfig {
  LabelPreset preset = LabelPreset::kSemanticKittiRaw;  ///< id convention of the input labels (algorithm §1, §8)
  LabelFormat format = LabelFormat::kAuto;               ///< how label files store the ids (algorithm §1)
  /// Raw id → stable class index (0..C−1) or −1 (known, dropped). Used when preset is kCustom; ids not listed are
  /// unknown.
  std::map<uint32_t, int> custom_map;
  /// Classes 7, 8, … beyond the paper's seven, in this order; none by default. The class count is
  /// C = 7 + extra_classes.size() ≤ kMaxClasses = 16, and the descriptors grow with it: C² slots of 3 entries per
  /// node (7 classes: 147-D, 16: 768-D), G1/G3 2·C² (98 → 512) and G2 C³ floats per frame (343 → 4,096 = 16 KB,
  /// stored for every frame of the database; retrieval time grows in proportion).
  std::vector<ExtraClass> extra_classes;

  /// C: the paper's seven classes plus the extra ones.
  int numClasses() const { return kNumPaperClasses + static_cast<int>(extra_classes.size()); }
  /// Name of class @p c (kClassNames, then ExtraClass::name); "class-N" for an index outside 0..C−1.
  std::string className(int c) const;
};

/// Where a node's centre comes from (algorithm §2 and §11).
enum class CentreSource {
  kPoints,  ///< mean of the cluster's original points: invariant to the axis-aligned voxel grid (algorithm §11) [default]
  kVoxels,  ///< mean of the cluster's voxel centroids, as the authors' code (pcl::compute3DCentroid on voxels)
};

/// The height of a node's centre (algorithm §2, "Upright objects").
enum class CentreHeight {
  kPoints,  ///< the mean height of the cluster's points
  /// 0, the sensor's height: the node is where the object's vertical axis crosses the sensor's horizontal plane.
  /// For poles and trunks, whose points' mean height moves with the part of them in view (the beams that reach
  /// them, the cars in front), so that a revisit from farther or nearer finds it again (BENCHMARKS.md, "Upright
  /// objects at the sensor's height").
  kSensor,
};

/// Per-class clustering parameters (algorithm §2 table).
struct ClassClusterConfig {
  /// Voxel leaf (m); 0 = no downsampling. 0 or [0.001, 10]: the lower bound keeps the cells of points within
  /// ±kMaxCoordinate exact integers.
  double voxel = 0.0;
  double radius = 1.0;  ///< FEC radius r (m)
  int min_size = 20;    ///< minimum cluster size; counts voxels when voxel > 0, else points
  CentreHeight centre_height = CentreHeight::kPoints;  ///< the height of the node's centre
  /// Whether this class's nodes count in the loop score's node count (and score_c's) when they are not matched.
  /// false: they count only as matches, so a class a sensor rarely sees again from a few metres away (terrain
  /// on a 32-beam sensor, BENCHMARKS.md "Which classes repeat on a 32-beam sensor") adds evidence but never
  /// dilutes it; the nodes still shape every descriptor (algorithm §7.3, "Node count").
  bool score_unmatched = true;
};

struct ClusterConfig {
  /// Indexed by class: building, fence, vegetation, trunk, terrain, pole, traffic-sign, then the extra classes of
  /// LabelConfig::extra_classes in their order (Config::addClass appends both). One entry per class.
  std::vector<ClassClusterConfig> classes = {
      {0.4, 1.0, 200},  // building
      {0.4, 1.0, 20},   // fence
      {0.4, 1.0, 150},  // vegetation
      {0.0, 1.0, 20, CentreHeight::kSensor},  // trunk
      {0.4, 1.0, 150},                         // terrain
      {0.0, 1.0, 20, CentreHeight::kSensor},  // pole
      {0.0, 1.0, 20, CentreHeight::kSensor},  // traffic-sign
  };
  int max_neighbors = 100;         ///< FEC cap on neighbours per radius query, seed included (algorithm §2)
  /// Skip a cluster whose centre is this close (m, 3-D) to an accepted same-class one (algorithm §2).
  double duplicate_radius = 1.0;
  CentreSource centre = CentreSource::kPoints;  ///< node centre source (algorithm §11 [CHOICE])
};

/// Upper bound of GraphConfig::max_nodes: a graph of this size takes ~36 MB and a pair of them about a second.
inline constexpr int kMaxGraphNodes = 2000;

struct GraphConfig {
  /// σ_d: nodes are adjacent iff their distance is < σ_d (m, strict) (algorithm §3).
  double sigma_d = 30.0;
  /// Most nodes one frame's graph may have. The graph is dense: its memory and the
  /// association time grow with the square of the node count (1,000 nodes: 9 MB per graph). Real scans give
  /// 20–70 nodes (algorithm §2), so the default leaves 14× headroom. A scan with more clusters keeps the max_nodes
  /// with the most points (NodeExtractor; counted in ExtractionStats::capped_nodes); ready-made nodes above it
  /// (node files, LoopDetector::process(nodes), comparePair) are an error.
  int max_nodes = 1000;
  /// Let the path i→j→i compete for a slot, as the authors' code; such a winner leaves the slot empty
  /// (algorithm §3 [CHOICE]).
  bool allow_k_equals_i = false;
};

/// Order of the three sub-vector entries of a local-descriptor slot (algorithm §4).
enum class SubVectorOrder {
  kPaper,  ///< (a_i, a_j, a_k), vertex-rooted [default]
  kCode,   ///< (a_i, a_k, −a_j), the authors' code
};

/// Global descriptor variants (algorithm §5).
enum class GlobalMode {
  kG1,  ///< paper: 98-D fuzzy pooling of max a_k (floored at 0)
  kG2,  ///< code: 343-D, max 1 − cos θ_k [default: DescriptorConfig::global_mode]
  kG3,  ///< hybrid: 98-D fuzzy pooling of max 1 − cos θ_k (the first default)
};

/// What a slot's three entries measure (the paper's Table IV ablation). Each entry belongs to one triangle vertex.
enum class SubVectorKind {
  kDotProducts,  ///< a_v = the dot product of the two edges leaving vertex v (m²): angle and length [default]
  kAngles,       ///< cos of the interior angle at v: angle only (scale-free)
  kLengths,      ///< length of the side opposite v (m): length only
};

struct DescriptorConfig {
  SubVectorKind kind = SubVectorKind::kDotProducts;  ///< slot entries (algorithm §4; others for ablation)
  SubVectorOrder order = SubVectorOrder::kPaper;  ///< sub-vector entry order (algorithm §4 [CHOICE])
  /// Global descriptor Des^G (algorithm §5). [deviation: the first choice was G3; G2 has the highest retrieval
  /// recall@15 on all five simulated 2,000-frame sequences measured in BENCHMARKS.md ("Global descriptor")]
  GlobalMode global_mode = GlobalMode::kG2;
};

/// Nearest-neighbour search over global descriptors.
enum class RetrievalMethod {
  kBruteForce,  ///< exact linear scan (algorithm §5 [CHOICE]) [default]
  kKdTree,      ///< exact kd-tree search (nanoflann); frames at equal distance up to float rounding may swap
  /// Inverted file for large maps (algorithm §5 "Retrieval at scale"): FAISS k-means centroids over the stored keys,
  /// each frame in its nearest centroid's list; a query scans one-byte codes of the keys in the retrieval.ivf_probe
  /// nearest lists and ranks the nearest 4·K of them by the exact distance. Approximate (a true neighbour in an
  /// unscanned list is missed); the exact scan until
  /// retrieval.ivf_train_frames frames are stored. Needs sgtllc built with FAISS (libfaiss-dev).
  kIvf,
};

/// What a frame is stored and searched by.
enum class RetrievalKey {
  /// Per class-pair histogram of node-centre distances (retrieval/distance_histogram.h) [default]. [deviation: the
  /// paper's key is Des^G (algorithm §5), which changes by a whole cell when one node appears or vanishes;
  /// BENCHMARKS.md "Retrieval key"]
  kDistanceHistogram,
  kGlobalDescriptor,  ///< Des^G of DescriptorConfig::global_mode, as the paper and the authors' code
};

struct RetrievalConfig {
  RetrievalKey key = RetrievalKey::kDistanceHistogram;  ///< the stored, searched key
  /// Bins per class pair of the distance histogram (key histogram). 30 bins over 60 m with seven classes:
  /// 840 floats (3,360 bytes) per stored frame.
  int histogram_bins = 30;
  /// Distances (m) the histogram covers; node pairs this far apart or farther do not vote. [choice: 60 m
  /// rather than 20 puts a label-free revisit driven the other way among the candidates far more often;
  /// BENCHMARKS.md "Retrieval key"]
  double histogram_range = 60.0;
  int num_candidates = 15;   ///< K: candidates retrieved per query (algorithm §5)
  /// G: query q searches only frames with index ≤ q − G (algorithm §5 [CHOICE]). A sequence of at most G
  /// frames has no candidates at all (LoopDetector::firstSearchedFrame).
  int exclude_recent = 50;
  /// No query before this many frames are in the database (authors' code: 150).
  int warmup_frames = 0;
  RetrievalMethod method = RetrievalMethod::kBruteForce;  ///< search structure
  /// Lists of the inverted file (method ivf); 0: 2·√N at training, within [16, 16384].
  int ivf_lists = 0;
  /// Lists a query scans (method ivf). 20 of the 2,000 lists of a million-frame map found 0.995 of the exact
  /// top-15 in 1.5 ms of CPU on the harder of the two query sets of BENCHMARKS.md "One-byte codes in the lists".
  int ivf_probe = 20;
  /// Frames stored before the inverted file is trained (method ivf); fewer are searched exactly. With
  /// ivf_lists 0 it is trained again each time the database has grown fourfold.
  int ivf_train_frames = 20000;
};

/// How the node similarity S[i][j] is formed (algorithm §6).
enum class NodeScore {
  kRatio,  ///< matched slots / valid query slots, as the authors' code [default]
  kCount,  ///< raw count of matched slots, as the paper's Algorithm 1
};

struct AssociationConfig {
  double sigma_1 = 0.9;          ///< σ_1: a slot matches iff cos(u, v) > σ_1 (algorithm §6)
  double max_delta_aj = 100.0;   ///< ... and |Δa_j| < this (m²); the code's √|Δ| < 10 test (algorithm §6)
  /// σ_2: accept the best candidate node iff S ≥ σ_2 (algorithm §6): a share of the slots with score ratio, a
  /// count of them (at most C², the slot count: 49 for the seven classes) with score count. [deviation: the paper's 0.3 starved opposite-direction
  /// revisits of associations; RANSAC rejects the wrong pairs. BENCHMARKS.md "Association and RANSAC sample"]
  double sigma_2 = 0.2;
  NodeScore score = NodeScore::kRatio;  ///< node similarity form (algorithm §6)
  /// Sub-vector entries compared, by vertex: bit 0 = v_i, bit 1 = v_j, bit 2 = v_k (ablation: drop one). The
  /// |Δa_j| test applies only to dot-product slots with the v_j entry kept.
  unsigned entries = 0b111;
};

/// Upper bound of Config::threads.
inline constexpr int kMaxThreads = 256;

/// Everything the pipeline reads. Modules receive only their own sub-struct.
struct Config {
  LabelConfig labels;
  /// Where the per-point classes come from: the label files (labels.*) or the geometric labeller
  /// (docs/labeller.md). With source geometric no label file is read, labels.preset is not used (the labeller
  /// speaks SemanticKITTI raw ids) and labels.extra_classes must be empty (it gives only the paper's classes).
  LabellerConfig labeller;
  ClusterConfig cluster;
  GraphConfig graph;
  DescriptorConfig descriptor;
  RetrievalConfig retrieval;
  AssociationConfig association;
  VerificationConfig verification;
  /// Fine registration of loop poses (point-to-plane ICP; `sgtllc pair` by default, online as an option).
  RegistrationConfig registration;
  int threads = 1;  ///< worker threads for candidate verification; results do not depend on it
  /// Pose-graph back end (`sgtllc run --odometry`, `sgtllc optimize`): plain data here, the optimiser is the
  /// separate sgtllc_backend library (docs/backend.md).
  backend::BackendConfig backend;

  /// C = labels.numClasses().
  int numClasses() const { return labels.numClasses(); }

  /// Declares an extra class (labels.extra_classes) with its clustering parameters (cluster.classes); returns its
  /// class index. Config::validate() checks the name and ids.
  int addClass(ExtraClass extra, const ClassClusterConfig& cluster = {});

  /// Throws ConfigError for the first field whose value is out of its range in the settings table, e.g.
  /// "verification.sigma_4 = 5 is out of range [0, 1]", for settings that contradict each other, or an invalid
  /// class set
  /// ("labels.extra_classes[0].name: 'pole' is one of the paper's classes").
  void validate() const;
};

/// The label space of the node extraction: @p config.labels, or with labeller.source geometric the
/// SemanticKITTI raw ids the geometric labeller writes (LabelConfig{}).
LabelConfig effectiveLabelConfig(const Config& config);
/// The same for a label set and labeller settings: with labeller.source hybrid, the SemanticKITTI ids too when it
/// splits anything off (hybridSplits in labels.h), else @p labels.
LabelConfig effectiveLabelConfig(const LabelConfig& labels, const LabellerConfig& labeller);

/// A configuration value out of its allowed range. key() is the YAML key (`verification.sigma_4`), so a reader
/// of a configuration file can point at the offending line.
class ConfigError : public Error {
 public:
  ConfigError(std::string key, const std::string& message) : Error(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

}  // namespace sgtllc
