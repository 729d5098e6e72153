// LoopDetector, compare_pair and compare_nodes (include/sgtllc/detector.h). Arrays are checked and converted
// with the GIL held; the library call itself runs with the GIL released, so other Python threads keep running.
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "opaque.h"
#include "sgtllc/detector.h"
#include "sgtllc/map/map.h"

namespace sgtllc::python {
namespace {

/// The C++ detector is not thread-safe; with the GIL released, two Python threads could enter it at once, so
/// each call holds the detector's own lock.
struct PyLoopDetector {
  explicit PyLoopDetector(const Config& config) : detector(config) {}
  PyLoopDetector(const Config& config, FrameDatabase database, std::vector<Footprint> footprints)
      : detector(config, std::move(database), std::move(footprints)) {}
  LoopDetector detector;
  std::mutex mutex;
};

const Config& orDefault(const Config* config) {
  static const Config defaults;
  return config ? *config : defaults;
}

}  // namespace

void bindDetector(py::module_& m) {
  py::class_<PyLoopDetector>(m, "LoopDetector",
                             "Online SGT-LLC: each processed frame is described, queried against the frames at\n"
                             "least retrieval.exclude_recent older, verified and then stored.")
      .def(py::init<const Config&>(), py::arg("config") = Config{},
           "Raises ConfigError if the configuration is invalid. The detector keeps a copy of it.")
      .def(py::init([](const map::Map& saved, const Config& config) {
             map::checkCompatible(saved, config, "map");
             map::Map copy = copyMap(saved);
             return std::make_unique<PyLoopDetector>(config, std::move(copy.database), std::move(copy.footprints));
           }),
           py::arg("map"), py::arg("config") = Config{},
           "Resumes over the frames of a Map: the next frame is numbered map.num_frames and is searched as if\n"
           "this detector had processed the map's frames. Raises sgtllc.Error if the map's fields differ.")
      .def("process",
           [](PyLoopDetector& d, const ArrayLike& points, const ArrayLike& labels, bool drop_nonfinite) {
             LabeledCloud cloud = cloudFromArrays(points, labels, "", drop_nonfinite);
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(d.mutex);
             return d.detector.process(cloud);
           },
           py::arg("points"), py::arg("labels"), py::arg("drop_nonfinite") = false,
           "Processes a labelled scan: points (N, 3) or (N, 4) float (sensor frame, m; a 4th column is ignored),\n"
           "labels (N,) integer raw ids. Returns a FrameResult. A NaN/Inf coordinate raises ValueError unless\n"
           "drop_nonfinite=True, which lets the detector drop and count such points as the CLI does.")
      .def("process_nodes",
           [](PyLoopDetector& d, const ArrayLike& centres, const ArrayLike& classes) {
             std::vector<Node> nodes = nodesFromArrays(centres, classes, "", d.detector.config().numClasses());
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(d.mutex);
             return d.detector.process(std::move(nodes));
           },
           py::arg("centres"), py::arg("classes"),
           "Processes a frame given as ready-made nodes: centres (N, 3) float (m), classes (N,) integer stable\n"
           "class indices 0..C-1. More than graph.max_nodes nodes raise sgtllc.Error; the frame is then not stored.")
      .def("first_searched_frame", [](PyLoopDetector& d) { return d.detector.firstSearchedFrame(); },
           "Index of the first frame whose query searches the database.")
      .def_property_readonly("num_frames", [](PyLoopDetector& d) { return d.detector.numFrames(); },
                             "frames processed so far")
      .def_property_readonly("config", [](PyLoopDetector& d) { return d.detector.config(); },
                             "a copy of the detector's configuration")
      .def("nodes",
           [](PyLoopDetector& d, int frame) {
             const int n = d.detector.numFrames();
             if (n == 0) throw py::index_error("frame " + std::to_string(frame) + ": the detector holds no frames");
             if (frame < 0 || frame >= n) {
               throw py::index_error("frame " + std::to_string(frame) + " is not in 0.." + std::to_string(n - 1));
             }
             return nodesToArrays(d.detector.database().nodes(frame));
           },
           py::arg("frame"), "(centres (N, 3) float64, classes (N,) int32) of a stored frame.")
      .def("to_map",
           [](PyLoopDetector& d, std::optional<std::vector<std::string>> names, const py::object& poses) {
             std::vector<std::string> frame_names;
             if (names) {
               frame_names = std::move(*names);
             } else {
               for (int f = 0; f < d.detector.numFrames(); ++f) frame_names.push_back(std::to_string(f));
             }
             std::vector<Eigen::Matrix4d> frame_poses;
             if (!poses.is_none()) frame_poses = rigidPosesFromArray(poses, "poses");
             std::lock_guard<std::mutex> lock(d.mutex);
             return std::make_shared<map::Map>(map::makeMap(d.detector.database(), d.detector.config(),
                                                            std::move(frame_names), std::move(frame_poses),
                                                            d.detector.footprints()));
           },
           py::arg("names") = py::none(), py::arg("poses") = py::none(),
           "The stored frames as a Map (copied): names (one per frame; default '0', '1', ...) and optional\n"
           "(N, 4, 4) poses T_world_lidar (rigid: rotations orthonormal within 1e-3, last row 0 0 0 1, as the command\n"
           "line's trajectory files). Raises sgtllc.Error for a wrong count, a repeated name or a non-rigid pose.");

  m.def("compare_pair",
        [](const ArrayLike& qp, const ArrayLike& ql, const ArrayLike& mp, const ArrayLike& ml,
           const Config* config, bool drop_nonfinite) {
          const LabeledCloud query = cloudFromArrays(qp, ql, "query_", drop_nonfinite);
          const LabeledCloud match = cloudFromArrays(mp, ml, "match_", drop_nonfinite);
          const Config& c = orDefault(config);
          py::gil_scoped_release release;
          return comparePair(query, match, c);
        },
        py::arg("query_points"), py::arg("query_labels"), py::arg("match_points"), py::arg("match_labels"),
        py::arg("config") = py::none(), py::arg("drop_nonfinite") = false,
        "Is the query scan a revisit of the match scan, and where is it in the match frame? Arrays as in\n"
        "LoopDetector.process; config None = the defaults. Returns a PairResult (what `sgtllc pair` prints).");
  m.def("compare_nodes",
        [](const ArrayLike& qc, const ArrayLike& ql, const ArrayLike& mc, const ArrayLike& ml,
           const Config* config) {
          const Config& c = orDefault(config);
          std::vector<Node> query = nodesFromArrays(qc, ql, "query_", c.numClasses());
          std::vector<Node> match = nodesFromArrays(mc, ml, "match_", c.numClasses());
          py::gil_scoped_release release;
          return comparePair(std::move(query), std::move(match), c);
        },
        py::arg("query_centres"), py::arg("query_classes"), py::arg("match_centres"), py::arg("match_classes"),
        py::arg("config") = py::none(),
        "compare_pair for ready-made node sets: centres (N, 3) float, classes (N,) integer class indices.");
}

}  // namespace sgtllc::python
