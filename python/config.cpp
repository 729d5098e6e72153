// Config and its sections, field by field as in include/sgtllc/config.h (where each field's range and meaning is
// documented). Adding a field to a C++ section is one `.def_readwrite` line here and one line in sgtllc.pyi.
#include <pybind11/stl.h>
#include <pybind11/stl_bind.h>

#include "bindings.h"
#include "opaque.h"
#include "sgtllc/io/config_yaml.h"

namespace sgtllc::python {
namespace {

void enums(py::module_& m) {
  py::enum_<LabelPreset>(m, "LabelPreset", "How raw per-point ids map to the stable classes (YAML labels.preset).")
      .value("SEMANTIC_KITTI_RAW", LabelPreset::kSemanticKittiRaw, "SemanticKITTI raw ids (yaml: semantickitti)")
      .value("SEMANTIC_KITTI_LEARNING", LabelPreset::kSemanticKittiLearning, "SemanticKITTI learning ids 13..19")
      .value("MULRAN", LabelPreset::kMulRan, "MulRan: train id = label + 1")
      .value("MCD", LabelPreset::kMcd, "MCD: the authors' 29-entry map")
      .value("CUSTOM", LabelPreset::kCustom, "LabelConfig.custom_map only")
      .value("NUSCENES", LabelPreset::kNuScenes, "nuScenes-lidarseg: manmade, barrier, vegetation, terrain kept");
  py::enum_<LabelFormat>(m, "LabelFormat", "How label files store the ids (YAML labels.format).")
      .value("AUTO", LabelFormat::kAuto, "by the file size: 4 bytes a point uint32, 1 byte uint8 (default)")
      .value("UINT32", LabelFormat::kUint32, "one uint32 a point (SemanticKITTI)")
      .value("UINT8", LabelFormat::kUint8, "one byte a point (nuScenes-lidarseg)");
  py::enum_<CentreSource>(m, "CentreSource", "Where a node's centre comes from (cluster.centre).")
      .value("POINTS", CentreSource::kPoints, "mean of the cluster's original points (default)")
      .value("VOXELS", CentreSource::kVoxels, "mean of the cluster's voxel centroids (authors' code)");
  py::enum_<SubVectorOrder>(m, "SubVectorOrder", "Order of a slot's three entries (descriptor.order).")
      .value("PAPER", SubVectorOrder::kPaper, "(a_i, a_j, a_k) (default)")
      .value("CODE", SubVectorOrder::kCode, "(a_i, a_k, -a_j), the authors' code");
  py::enum_<GlobalMode>(m, "GlobalMode", "Global descriptor variant (descriptor.global_mode).")
      .value("G1", GlobalMode::kG1, "98-D fuzzy pooling of max a_k")
      .value("G2", GlobalMode::kG2, "343-D, max 1 - cos θ_k (default)")
      .value("G3", GlobalMode::kG3, "98-D fuzzy pooling of max 1 - cos θ_k");
  py::enum_<SubVectorKind>(m, "SubVectorKind", "What a slot's entries measure (descriptor.kind).")
      .value("DOT_PRODUCTS", SubVectorKind::kDotProducts, "dot products of the edges at each vertex (default)")
      .value("ANGLES", SubVectorKind::kAngles, "cosines of the interior angles")
      .value("LENGTHS", SubVectorKind::kLengths, "lengths of the opposite sides");
  py::enum_<RetrievalMethod>(m, "RetrievalMethod", "Nearest-neighbour search (retrieval.method).")
      .value("BRUTE_FORCE", RetrievalMethod::kBruteForce, "exact linear scan (default)")
      .value("KD_TREE", RetrievalMethod::kKdTree, "exact kd-tree search")
      .value("IVF", RetrievalMethod::kIvf, "inverted file for large maps (approximate; needs FAISS)");
  py::enum_<RetrievalKey>(m, "RetrievalKey", "The stored, searched key (retrieval.key).")
      .value("DISTANCE_HISTOGRAM", RetrievalKey::kDistanceHistogram,
             "per class-pair histogram of node-centre distances (default)")
      .value("GLOBAL_DESCRIPTOR", RetrievalKey::kGlobalDescriptor, "Des^G of descriptor.global_mode");
  py::enum_<NodeScore>(m, "NodeScore", "Node similarity form (association.score).")
      .value("RATIO", NodeScore::kRatio, "matched slots / valid query slots (default)")
      .value("COUNT", NodeScore::kCount, "raw count of matched slots");
  py::enum_<ScoreFormula>(m, "ScoreFormula", "Formula of score (verification.score_formula).")
      .value("PAPER", ScoreFormula::kPaper, "n_in / |LA|")
      .value("LEGACY", ScoreFormula::kLegacy, "(n_in - 1) / |LA|, the authors' code")
      .value("OVERLAP", ScoreFormula::kOverlap, "n_in / max(M, N) (default)");
}

void sections(py::module_& m) {
  py::class_<ExtraClass>(m, "ExtraClass", "A class beyond the paper's seven (labels.extra_classes).")
      .def(py::init([](std::string name, std::vector<uint32_t> ids) { return ExtraClass{std::move(name), std::move(ids)}; }),
           py::arg("name"), py::arg("ids") = std::vector<uint32_t>{})
      .def_readwrite("name", &ExtraClass::name, "lower-case name, as in cluster.NAME")
      // A tuple, so that `extra.ids.append(…)` fails instead of changing a copy; assign a new list instead.
      .def_property("ids", [](const ExtraClass& e) { return py::tuple(py::cast(e.ids)); },
                    [](ExtraClass& e, std::vector<uint32_t> ids) { e.ids = std::move(ids); },
                    "raw ids (0..65535) that map to this class")
      .def("__repr__", [](const ExtraClass& e) { return "ExtraClass('" + e.name + "', " + py::repr(py::cast(e.ids)).cast<std::string>() + ")"; });
  py::bind_vector<std::vector<ExtraClass>>(m, "ExtraClassList");
  py::bind_map<std::map<uint32_t, int>>(m, "CustomLabelMap");

  py::class_<LabelConfig>(m, "LabelConfig", "Label convention and class set (labels.*).")
      .def(py::init<>())
      .def_readwrite("preset", &LabelConfig::preset, "id convention of the input labels")
      .def_readwrite("format", &LabelConfig::format, "how label files store the ids")
      .def_readwrite("custom_map", &LabelConfig::custom_map, "raw id -> class index or -1 (preset CUSTOM)")
      .def_readwrite("extra_classes", &LabelConfig::extra_classes, "classes 7, 8, ... beyond the paper's seven")
      .def("num_classes", &LabelConfig::numClasses, "C: the paper's seven plus the extra classes")
      .def("class_name", &LabelConfig::className, py::arg("c"), "name of class index c");

  py::class_<ClassClusterConfig>(m, "ClassClusterConfig", "Per-class clustering (cluster.NAME.*).")
      .def(py::init([](double voxel, double radius, int min_size) { return ClassClusterConfig{voxel, radius, min_size}; }),
           py::arg("voxel") = 0.0, py::arg("radius") = 1.0, py::arg("min_size") = 20)
      .def_readwrite("voxel", &ClassClusterConfig::voxel, "voxel leaf (m); 0 = no downsampling")
      .def_readwrite("radius", &ClassClusterConfig::radius, "FEC radius r (m)")
      .def_readwrite("min_size", &ClassClusterConfig::min_size, "minimum cluster size (voxels if voxel > 0, else points)");
  py::bind_vector<std::vector<ClassClusterConfig>>(m, "ClassClusterConfigList");

  py::class_<ClusterConfig>(m, "ClusterConfig", "Clustering (cluster.*).")
      .def(py::init<>())
      .def_readwrite("classes", &ClusterConfig::classes, "one ClassClusterConfig per class, in class order")
      .def_readwrite("max_neighbors", &ClusterConfig::max_neighbors, "FEC neighbour cap per radius query")
      .def_readwrite("duplicate_radius", &ClusterConfig::duplicate_radius, "same-class duplicate radius (m)")
      .def_readwrite("centre", &ClusterConfig::centre, "node centre source");

  py::class_<GraphConfig>(m, "GraphConfig", "Semantic graph (graph.*).")
      .def(py::init<>())
      .def_readwrite("sigma_d", &GraphConfig::sigma_d, "σ_d: nodes adjacent iff distance < σ_d (m)")
      .def_readwrite("max_nodes", &GraphConfig::max_nodes, "most nodes per frame")
      .def_readwrite("allow_k_equals_i", &GraphConfig::allow_k_equals_i, "let the path i->j->i compete for a slot");

  py::class_<DescriptorConfig>(m, "DescriptorConfig", "Local and global descriptors (descriptor.*).")
      .def(py::init<>())
      .def_readwrite("kind", &DescriptorConfig::kind, "slot entries")
      .def_readwrite("order", &DescriptorConfig::order, "sub-vector entry order")
      .def_readwrite("global_mode", &DescriptorConfig::global_mode, "global descriptor variant");

  py::class_<RetrievalConfig>(m, "RetrievalConfig", "Candidate retrieval (retrieval.*).")
      .def(py::init<>())
      .def_readwrite("num_candidates", &RetrievalConfig::num_candidates, "K: candidates per query")
      .def_readwrite("exclude_recent", &RetrievalConfig::exclude_recent, "G: query q searches frames <= q - G")
      .def_readwrite("warmup_frames", &RetrievalConfig::warmup_frames, "no query before this many frames")
      .def_readwrite("method", &RetrievalConfig::method, "search structure")
      .def_readwrite("key", &RetrievalConfig::key, "the stored, searched key")
      .def_readwrite("histogram_bins", &RetrievalConfig::histogram_bins, "bins per class pair of the distance histogram")
      .def_readwrite("histogram_range", &RetrievalConfig::histogram_range, "distances binned by the histogram (m)")
      .def_readwrite("ivf_lists", &RetrievalConfig::ivf_lists, "inverted-file lists (0: 2 sqrt(N) at training)")
      .def_readwrite("ivf_probe", &RetrievalConfig::ivf_probe, "inverted-file lists scanned per query")
      .def_readwrite("ivf_train_frames", &RetrievalConfig::ivf_train_frames, "frames before the inverted file trains");

  py::class_<AssociationConfig>(m, "AssociationConfig", "Node association (association.*).")
      .def(py::init<>())
      .def_readwrite("sigma_1", &AssociationConfig::sigma_1, "σ_1: a slot matches iff cos(u, v) > σ_1")
      .def_readwrite("max_delta_aj", &AssociationConfig::max_delta_aj, "... and |Δa_j| < this (m²)")
      .def_readwrite("sigma_2", &AssociationConfig::sigma_2, "σ_2: accept the best node iff S >= σ_2")
      .def_readwrite("score", &AssociationConfig::score, "node similarity form")
      .def_readwrite("entries", &AssociationConfig::entries, "entries compared: bit 0 v_i, bit 1 v_j, bit 2 v_k");

  py::class_<VerificationConfig>(m, "VerificationConfig", "Verification and the loop decision (verification.*).")
      .def(py::init<>())
      .def_readwrite("sigma_3", &VerificationConfig::sigma_3, "σ_3: skip a candidate if score_c < σ_3")
      .def_readwrite("min_associations", &VerificationConfig::min_associations, "... or if |LA| is below this")
      .def_readwrite("ransac_iterations", &VerificationConfig::ransac_iterations, "RANSAC hypotheses per candidate")
      .def_readwrite("ransac_sample_size", &VerificationConfig::ransac_sample_size, "node pairs per hypothesis")
      .def_readwrite("sample_with_replacement", &VerificationConfig::sample_with_replacement, "draw with replacement")
      .def_readwrite("inlier_threshold", &VerificationConfig::inlier_threshold, "inlier iff residual < this (m)")
      .def_readwrite("min_inliers", &VerificationConfig::min_inliers, "accept a hypothesis with >= this many inliers")
      .def_readwrite("min_inlier_fraction", &VerificationConfig::min_inlier_fraction, "... and >= this share of |LA|")
      .def_readwrite("ransac_confidence", &VerificationConfig::ransac_confidence, "adaptive RANSAC stop probability")
      .def_readwrite("select_margin", &VerificationConfig::select_margin,
                     "top-1: the closest candidate scoring within this of the best")
      .def_readwrite("lateral_distance", &VerificationConfig::lateral_distance,
                     "a top-1 estimated this far (m) or more is lateral")
      .def_readwrite("neighbour_frames", &VerificationConfig::neighbour_frames,
                     "also verify the top-1 loop's database neighbours within this many frames; 0 = off")
      .def_readwrite("offset_decay_start", &VerificationConfig::offset_decay_start,
                     "score decays linearly for an estimated offset beyond this (m)")
      .def_readwrite("offset_decay_end", &VerificationConfig::offset_decay_end,
                     "... to 0 at this offset (m); 0 = no decay")
      .def_readwrite("min_footprint_overlap", &VerificationConfig::min_footprint_overlap,
                     "reject a verified candidate whose pose puts less than this share of the query's structure "
                     "cells on the match's; 0 = off")
      .def_readwrite("footprint_cell", &VerificationConfig::footprint_cell, "side of a footprint cell (m)")
      .def_readwrite("footprint_radius", &VerificationConfig::footprint_radius,
                     "footprints reach this far from the sensor (m)")
      .def_readwrite("score_formula", &VerificationConfig::score_formula, "score formula")
      .def_readwrite("max_tilt_deg", &VerificationConfig::max_tilt_deg,
                     "RANSAC skips a rotation tilting the up axis more than this (deg); 180 = no check")
      .def_readwrite("guided_matching", &VerificationConfig::guided_matching,
                     "after RANSAC, pair the nodes its pose puts together (score_formula overlap only)")
      .def_readwrite("consistency_pairs", &VerificationConfig::consistency_pairs,
                     "when the descriptors' pairs give no loop, verify the largest consistent set of each query "
                     "node's this many most similar same-class nodes; 0 = off")
      .def_readwrite("weak_inliers", &VerificationConfig::weak_inliers,
                     "a loop of at most this many inliers needs weak_min_footprint; 0 = no such rule")
      .def_readwrite("weak_min_footprint", &VerificationConfig::weak_min_footprint,
                     "footprint share a loop of few inliers, or of the consistency path, needs")
      .def_readwrite("use_ransac", &VerificationConfig::use_ransac, "false: score = score_c, pose from all pairs")
      .def_readwrite("sigma_4", &VerificationConfig::sigma_4, "σ_4: a loop iff the best score > σ_4")
      .def_readwrite("seed", &VerificationConfig::seed, "RANSAC random seed");
}

}  // namespace

void bindConfig(py::module_& m) {
  enums(m);
  sections(m);
  py::class_<Config>(m, "Config",
                     "Everything the pipeline reads, nested as the C++ sgtllc::Config and the YAML keys.\n"
                     "Values are checked by validate() (and by LoopDetector and compare_pair), which raises\n"
                     "ConfigError naming the key, e.g. 'verification.sigma_4 = 5 is out of range [0, 1]'.")
      .def(py::init<>(), "The defaults (what `sgtllc config` prints).")
      .def_readwrite("labels", &Config::labels, "label convention and class set (labels.*)")
      .def_readwrite("labeller", &Config::labeller, "where the classes come from; the geometric labeller (labeller.*)")
      .def_readwrite("cluster", &Config::cluster, "clustering (cluster.*)")
      .def_readwrite("graph", &Config::graph, "semantic graph (graph.*)")
      .def_readwrite("descriptor", &Config::descriptor, "descriptors (descriptor.*)")
      .def_readwrite("retrieval", &Config::retrieval, "candidate retrieval (retrieval.*)")
      .def_readwrite("registration", &Config::registration, "fine registration of loop poses (registration.*)")
      .def_readwrite("association", &Config::association, "node association (association.*)")
      .def_readwrite("verification", &Config::verification, "verification and loop decision (verification.*)")
      .def_readwrite("threads", &Config::threads, "worker threads for candidate verification")
      .def_readwrite("backend", &Config::backend, "pose-graph back end settings")
      .def("num_classes", &Config::numClasses, "C = labels.num_classes()")
      .def("add_class", &Config::addClass, py::arg("extra"), py::arg("cluster") = ClassClusterConfig{},
           "Declares an extra class with its clustering parameters; returns its class index.")
      .def("validate", &Config::validate, "Raises ConfigError for the first field out of range.")
      .def_static("from_yaml", &io::loadConfig, py::arg("path"),
                  "Reads a YAML file (keys as `sgtllc config` prints them); omitted keys keep their defaults.")
      .def_static("from_yaml_string", &io::parseConfig, py::arg("yaml"), py::arg("source") = "<config>",
                  "Parses YAML text; errors name `source`, the line and the key.")
      .def("to_yaml", &io::configToYaml, "The whole configuration as commented YAML (from_yaml reads it back).")
      .def("__copy__", [](const Config& c) { return Config(c); })
      .def("__deepcopy__", [](const Config& c, const py::dict&) { return Config(c); }, py::arg("memo"))
      .def("__eq__", [](const Config& a, const Config& b) { return io::configToYaml(a) == io::configToYaml(b); })
      .def("__repr__", [](const Config&) { return std::string("<sgtllc.Config; to_yaml() shows every field>"); });
}

}  // namespace sgtllc::python
