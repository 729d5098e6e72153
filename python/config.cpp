// Config and its sections (include/sgtllc/config.h). Their settings are properties made from the settings table
// (settings.h); what is bound here by hand is the structure (sections, lists, maps) and the settings with a syntax
// of their own.
#include <pybind11/stl.h>
#include <pybind11/stl_bind.h>

#include "bindings.h"
#include "opaque.h"
#include "settings.h"
#include "sgtllc/io/config_reference.h"
#include "sgtllc/io/config_yaml.h"

namespace sgtllc::python {
namespace {

void enums(py::module_& m) {
  choiceEnum<LabelPreset>(m, "LabelPreset", "How raw per-point ids map to the stable classes (YAML labels.preset).")
      .value("SEMANTIC_KITTI_RAW", LabelPreset::kSemanticKittiRaw, "SemanticKITTI raw ids (yaml: semantickitti)")
      .value("SEMANTIC_KITTI_LEARNING", LabelPreset::kSemanticKittiLearning, "SemanticKITTI learning ids 13..19")
      .value("MULRAN", LabelPreset::kMulRan, "MulRan: train id = label + 1")
      .value("MCD", LabelPreset::kMcd, "MCD: the authors' 29-entry map")
      .value("CUSTOM", LabelPreset::kCustom, "LabelConfig.custom_map only")
      .value("NUSCENES", LabelPreset::kNuScenes, "nuScenes-lidarseg: manmade, barrier, vegetation, terrain kept");
  choiceEnum<LabelFormat>(m, "LabelFormat", "How label files store the ids (YAML labels.format).")
      .value("AUTO", LabelFormat::kAuto, "by the file size: 4 bytes a point uint32, 1 byte uint8 (default)")
      .value("UINT32", LabelFormat::kUint32, "one uint32 a point (SemanticKITTI)")
      .value("UINT8", LabelFormat::kUint8, "one byte a point (nuScenes-lidarseg)");
  choiceEnum<CentreSource>(m, "CentreSource", "Where a node's centre comes from (cluster.centre).")
      .value("POINTS", CentreSource::kPoints, "mean of the cluster's original points (default)")
      .value("VOXELS", CentreSource::kVoxels, "mean of the cluster's voxel centroids (authors' code)");
  choiceEnum<CentreHeight>(m, "CentreHeight", "The height of a node's centre (cluster.NAME.centre_height).")
      .value("POINTS", CentreHeight::kPoints, "the mean height of the cluster's points")
      .value("SENSOR", CentreHeight::kSensor, "0, the sensor's height: upright objects (pole, trunk, sign)");
  choiceEnum<SubVectorOrder>(m, "SubVectorOrder", "Order of a slot's three entries (descriptor.order).")
      .value("PAPER", SubVectorOrder::kPaper, "(a_i, a_j, a_k) (default)")
      .value("CODE", SubVectorOrder::kCode, "(a_i, a_k, -a_j), the authors' code");
  choiceEnum<GlobalMode>(m, "GlobalMode", "Global descriptor variant (descriptor.global_mode).")
      .value("G1", GlobalMode::kG1, "98-D fuzzy pooling of max a_k")
      .value("G2", GlobalMode::kG2, "343-D, max 1 - cos θ_k (default)")
      .value("G3", GlobalMode::kG3, "98-D fuzzy pooling of max 1 - cos θ_k");
  choiceEnum<SubVectorKind>(m, "SubVectorKind", "What a slot's entries measure (descriptor.kind).")
      .value("DOT_PRODUCTS", SubVectorKind::kDotProducts, "dot products of the edges at each vertex (default)")
      .value("ANGLES", SubVectorKind::kAngles, "cosines of the interior angles")
      .value("LENGTHS", SubVectorKind::kLengths, "lengths of the opposite sides");
  choiceEnum<RetrievalMethod>(m, "RetrievalMethod", "Nearest-neighbour search (retrieval.method).")
      .value("BRUTE_FORCE", RetrievalMethod::kBruteForce, "exact linear scan (default)")
      .value("KD_TREE", RetrievalMethod::kKdTree, "exact kd-tree search")
      .value("IVF", RetrievalMethod::kIvf, "inverted file for large maps (approximate; needs FAISS)");
  choiceEnum<RetrievalKey>(m, "RetrievalKey", "The stored, searched key (retrieval.key).")
      .value("DISTANCE_HISTOGRAM", RetrievalKey::kDistanceHistogram,
             "per class-pair histogram of node-centre distances (default)")
      .value("GLOBAL_DESCRIPTOR", RetrievalKey::kGlobalDescriptor, "Des^G of descriptor.global_mode");
  choiceEnum<NodeScore>(m, "NodeScore", "Node similarity form (association.score).")
      .value("RATIO", NodeScore::kRatio, "matched slots / valid query slots (default)")
      .value("COUNT", NodeScore::kCount, "raw count of matched slots");
  choiceEnum<ScoreFormula>(m, "ScoreFormula", "Formula of score (verification.score_formula).")
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

  settingsClass<LabelConfig>(m, "LabelConfig", "Label convention and class set (labels.*).")
      .def(py::init<>())
      .def_readwrite("custom_map", &LabelConfig::custom_map, "raw id -> class index or -1 (preset CUSTOM)")
      .def_readwrite("extra_classes", &LabelConfig::extra_classes, "classes 7, 8, ... beyond the paper's seven")
      .def("num_classes", &LabelConfig::numClasses, "C: the paper's seven plus the extra classes")
      .def("class_name", &LabelConfig::className, py::arg("c"), "name of class index c");

  settingsClass<ClassClusterConfig>(m, "ClassClusterConfig", "Per-class clustering (cluster.NAME.*).")
      .def(py::init([](double voxel, double radius, int min_size, CentreHeight centre_height, bool score_unmatched) {
             return ClassClusterConfig{voxel, radius, min_size, centre_height, score_unmatched};
           }),
           py::arg("voxel") = 0.0, py::arg("radius") = 1.0, py::arg("min_size") = 20,
           py::arg("centre_height") = CentreHeight::kPoints, py::arg("score_unmatched") = true);
  py::bind_vector<std::vector<ClassClusterConfig>>(m, "ClassClusterConfigList");

  settingsClass<ClusterConfig>(m, "ClusterConfig", "Clustering (cluster.*).")
      .def(py::init<>())
      .def_readwrite("classes", &ClusterConfig::classes, "one ClassClusterConfig per class, in class order");

  settingsClass<GraphConfig>(m, "GraphConfig", "Semantic graph (graph.*).")
      .def(py::init<>());

  settingsClass<DescriptorConfig>(m, "DescriptorConfig", "Local and global descriptors (descriptor.*).")
      .def(py::init<>());

  settingsClass<RetrievalConfig>(m, "RetrievalConfig", "Candidate retrieval (retrieval.*).")
      .def(py::init<>());

  settingsClass<AssociationConfig>(m, "AssociationConfig", "Node association (association.*).")
      .def(py::init<>())
      .def_readwrite("entries", &AssociationConfig::entries, "entries compared: bit 0 v_i, bit 1 v_j, bit 2 v_k");

  settingsClass<VerificationConfig>(m, "VerificationConfig", "Verification and the loop decision (verification.*).")
      .def(py::init<>());
}

}  // namespace

void bindConfig(py::module_& m) {
  enums(m);
  sections(m);
  settingsClass<Config>(m, "Config", "Everything the pipeline reads, nested as the C++ sgtllc::Config and the YAML keys.\n"
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
      .def("reference", &io::configReference,
           "Every setting as Markdown tables: key, value, accepted values, meaning (`sgtllc config --markdown`).")
      .def("__copy__", [](const Config& c) { return Config(c); })
      .def("__deepcopy__", [](const Config& c, const py::dict&) { return Config(c); }, py::arg("memo"))
      .def("__eq__", [](const Config& a, const Config& b) { return io::configToYaml(a) == io::configToYaml(b); })
      .def("__repr__", [](const Config&) { return std::string("<sgtllc.Config; to_yaml() shows every field>"); });
}

}  // namespace sgtllc::python
