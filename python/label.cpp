// The geometric labeller (include/sgtllc/label/, docs/labeller.md): its settings (labeller.*) and label_scan, which
// takes an (N, 3) or (N, 4) array (intensity ignored) and returns the classes. The settings are
// properties made from the settings table (settings.h).
#include "arrays.h"
#include "bindings.h"
#include "settings.h"
#include "sgtllc/label/cloud_labeller.h"
#include "sgtllc/label/geometric_labeller.h"

namespace sgtllc::python {

void bindLabel(py::module_& m) {
  choiceEnum<LabelSource>(m, "LabelSource", "Where the per-point classes come from (labeller.source).")
      .value("FILE", LabelSource::kFile, "the label files read with the scans")
      .value("GEOMETRIC", LabelSource::kGeometric, "the scan's geometry alone (docs/labeller.md)")
      .value("HYBRID", LabelSource::kHybrid, "the label files, with poles and trunks their label set lacks split off by geometry");

  using G = GroundConfig;
  settingsClass<G>(m, "GroundConfig", "Ground segmentation (labeller.ground.*).")
      .def(py::init<>());

  using S = SegmentRuleConfig;
  settingsClass<S>(m, "SegmentRuleConfig", "Segments and class rules (labeller.segments.*).")
      .def(py::init<>());

  settingsClass<LabellerConfig>(m, "LabellerConfig", "Where the classes come from, and the geometric labeller (labeller.*).")
      .def(py::init<>())
      .def_readwrite("ground", &LabellerConfig::ground, "ground segmentation")
      .def_readwrite("segments", &LabellerConfig::segments, "segments and class rules");

  m.def(
      "label_scan",
      [](const py::handle& points, const LabellerConfig& config) {
        const std::vector<Eigen::Vector3f> pts = pointsFromArray(points, "points", true);  // NaN/Inf kept: the labeller drops them
        label::Labelling l;
        {
          py::gil_scoped_release release;
          l = label::GeometricLabeller(config).classify(pts);
        }
        const auto n = static_cast<py::ssize_t>(l.classes.size());
        return py::make_tuple(vectorToArray(std::move(l.classes), {n}), vectorToArray(std::move(l.ground), {n}));
      },
      py::arg("points"), py::arg("config") = LabellerConfig{},
      "Geometric labeller (docs/labeller.md): (points (N, 3) or (N, 4), intensity ignored) → (classes (N,) int8:\n"
      "0..6 as the stable classes, never 3 (trunk is merged into pole 5), −1 dropped; ground (N,) uint8).\n"
      "NaN/Inf points are dropped, never an error.");
  m.def(
      "apply_labeller",
      [](const py::handle& points, const py::handle& labels, const Config& config) {
        LabeledCloud cloud = cloudFromArrays(points, labels, "", true);
        const label::CloudLabeller labeller(config.labels, config.labeller);
        {
          py::gil_scoped_release release;
          if (labeller.changesLabels()) cloud = labeller.apply(std::move(cloud));
        }
        const auto n = static_cast<py::ssize_t>(cloud.labels.size());
        return vectorToArray(std::move(cloud.labels), {n});
      },
      py::arg("points"), py::arg("labels"), py::arg("config"),
      "The raw ids the node extraction sees under config.labeller.source ((N,) uint32): the labels as given for\n"
      "file, SemanticKITTI ids from the geometry for geometric (labels ignored), and for hybrid the labels with the\n"
      "poles and trunks their label set lacks split off by geometry (docs/labeller.md §6). A LoopDetector or\n"
      "compare_pair with the same config reads them as they are meant (SemanticKITTI ids for geometric and hybrid).");
  m.def(
      "label_scan_ids",
      [](const py::handle& points, const LabellerConfig& config) {
        const std::vector<Eigen::Vector3f> pts = pointsFromArray(points, "points", true);
        std::vector<uint32_t> ids;
        {
          py::gil_scoped_release release;
          ids = label::semanticKittiIds(label::GeometricLabeller(config).classify(pts));
        }
        const auto n = static_cast<py::ssize_t>(ids.size());
        return vectorToArray(std::move(ids), {n});
      },
      py::arg("points"), py::arg("config") = LabellerConfig{},
      "label_scan's classes as SemanticKITTI raw ids ((N,) uint32: building 50, fence 51, vegetation 70, pole 80,\n"
      "ground 40, dropped 0), the labels LoopDetector.process and compare_pair take: what `--labeller geometric`\n"
      "feeds the pipeline (docs/labeller.md).");
}

}  // namespace sgtllc::python
