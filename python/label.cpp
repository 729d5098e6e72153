// The geometric labeller (include/sgtllc/label/, docs/labeller.md): its settings (labeller.*) and label_scan, which
// takes an (N, 3) or (N, 4) array (intensity ignored) and returns the classes. Adding a field is one line here and
// one in sgtllc.pyi.
#include "arrays.h"
#include "bindings.h"
#include "sgtllc/label/cloud_labeller.h"
#include "sgtllc/label/geometric_labeller.h"

namespace sgtllc::python {

void bindLabel(py::module_& m) {
  py::enum_<LabelSource>(m, "LabelSource", "Where the per-point classes come from (labeller.source).")
      .value("FILE", LabelSource::kFile, "the label files read with the scans")
      .value("GEOMETRIC", LabelSource::kGeometric, "the scan's geometry alone (docs/labeller.md)")
      .value("HYBRID", LabelSource::kHybrid, "the label files, with poles and trunks their label set lacks split off by geometry");

  using G = GroundConfig;
  py::class_<G>(m, "GroundConfig", "Ground segmentation (labeller.ground.*).")
      .def(py::init<>())
      .def_readwrite("sectors", &G::sectors, "angular sectors of the polar grid")
      .def_readwrite("bin", &G::bin, "range bin (m)")
      .def_readwrite("max_range", &G::max_range, "farther points are not ground-tested (m)")
      .def_readwrite("min_range", &G::min_range, "nearer points do not estimate the ground height (m)")
      .def_readwrite("step", &G::step, "step a ground line may make between bins (m)")
      .def_readwrite("max_slope", &G::max_slope, "rise per metre a ground line may have")
      .def_readwrite("max_climb", &G::max_climb, "rise per metre from the sensor's ground height")
      .def_readwrite("tolerance", &G::tolerance, "points this far above the ground height or lower are ground (m)");

  using S = SegmentRuleConfig;
  py::class_<S>(m, "SegmentRuleConfig", "Segments and class rules (labeller.segments.*).")
      .def(py::init<>())
      .def_readwrite("voxel", &S::voxel, "voxel leaf of the segments (m)")
      .def_readwrite("min_points", &S::min_points, "smaller segments are dropped")
      .def_readwrite("min_voxel_points", &S::min_voxel_points, "a voxel's shape counts from this many points")
      .def_readwrite("pole_max_width", &S::pole_max_width, "pole: horizontal extent at most (m)")
      .def_readwrite("pole_min_height", &S::pole_min_height, "pole: vertical extent at least (m)")
      .def_readwrite("pole_slice_low", &S::pole_slice_low, "pole slice: from this height above the ground (m)")
      .def_readwrite("pole_slice_high", &S::pole_slice_high, "pole slice: up to this height (m)")
      .def_readwrite("pole_min_span", &S::pole_min_span, "pole slice: height a thin component spans (m)")
      .def_readwrite("pole_voxel", &S::pole_voxel, "pole slice: voxel leaf (m)")
      .def_readwrite("pole_radius", &S::pole_radius, "pole slice: radius around a pole axis (m)")
      .def_readwrite("pole_max_occluded", &S::pole_max_occluded,
                     "a pole is kept if at most this share of the points beside either side lie nearer [0, 1]")
      .def_readwrite("building_min_top", &S::building_min_top, "tall: reaches this high above the ground (m)")
      .def_readwrite("building_min_length", &S::building_min_length, "building: length at least (m)")
      .def_readwrite("fence_max_top", &S::fence_max_top, "fence: ends below this height (m)")
      .def_readwrite("fence_min_length", &S::fence_min_length, "fence: length at least (m)")
      .def_readwrite("fence_max_width", &S::fence_max_width, "fence: thickness at most (m)")
      .def_readwrite("min_wall_share", &S::min_wall_share, "building: share of wall voxels")
      .def_readwrite("min_fence_wall_share", &S::min_fence_wall_share, "fence: share of wall voxels")
      .def_readwrite("min_scatter_share", &S::min_scatter_share, "vegetation: share of scattered voxels");

  py::class_<LabellerConfig>(m, "LabellerConfig", "Where the classes come from, and the geometric labeller (labeller.*).")
      .def(py::init<>())
      .def_readwrite("source", &LabellerConfig::source, "LabelSource")
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
