// Map files and relocalization (include/sgtllc/map/, docs/relocalization.md): Map, load_map / Map.save, Relocalizer.
// The detector's to_map and resume live in detector.cpp with the detector.
#include <memory>
#include <mutex>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "sgtllc/map/map_file.h"
#include "sgtllc/map/relocalization_tracker.h"
#include "sgtllc/map/relocalizer.h"

namespace sgtllc::python {

map::Map copyMap(const map::Map& m) {
  map::Map copy;
  copy.config = m.config;
  copy.names = m.names;
  copy.poses = m.poses;
  copy.footprints = m.footprints;
  copy.sessions = m.sessions;
  copy.database = m.database.copy();  // with a trained inverted file, so Python searches as the CLI does
  return copy;
}

namespace {

/// Relocalizer queries are not thread-safe (a kd-tree database grows on the first query): one lock per object.
struct PyRelocalizer {
  PyRelocalizer(const map::Map& m, const Config& config, int num_candidates, double max_rotation_uncertainty_deg)
      : relocalizer(copyMap(m), config, "map", map::RelocalizerOptions{num_candidates, max_rotation_uncertainty_deg}) {}
  map::Relocalizer relocalizer;
  std::mutex mutex;
};

/// A stream over one relocalizer (kept alive by the binding); the relocalizer's lock guards both.
struct PyTracker {
  PyTracker(PyRelocalizer& r, const map::TrackingOptions& options) : owner(r), tracker(r.relocalizer, options) {}
  PyRelocalizer& owner;
  map::RelocalizationTracker tracker;
  void reset_() { tracker.reset(); }
};

}  // namespace

void bindMap(py::module_& m) {
  py::class_<map::Map, std::shared_ptr<map::Map>>(m, "Map",
                                                   "A saved loop database: frames (nodes and keys), names, optional "
                                                   "poses\nand the configuration fields they depend on "
                                                   "(docs/map-format.md).")
      .def_property_readonly("num_frames", &map::Map::size, "frames in the map")
      .def_property_readonly("names", [](const map::Map& mp) { return mp.names; }, "frame names, in frame order")
      .def_property_readonly("has_poses", &map::Map::hasPoses, "whether the frames have poses")
      .def_property_readonly("has_footprints", [](const map::Map& mp) { return !mp.footprints.empty(); },
                             "whether the frames keep their footprints (the footprint check in relocalization)")
      .def_property_readonly("poses",
                             [](const map::Map& mp) -> py::object {
                               if (!mp.hasPoses()) return py::none();
                               return posesToArray(mp.poses);
                             },
                             "(N, 4, 4) float64 T_world_lidar of every frame, or None")
      .def_property_readonly("sessions",
                             [](const map::Map& mp) {
                               std::vector<std::tuple<std::string, int, int>> out;
                               for (const map::MapSession& s : mp.sessions) out.emplace_back(s.name, s.first, s.frames);
                               return out;
                             },
                             "[(name, first_frame, frames)] the drives merged into the map (docs/sessions.md), or []\n"
                             "for a map of one drive")
      .def_property_readonly("config", [](const map::Map& mp) { return mp.config; },
                             "[(key, value)] the configuration fields the map depends on, as `sgtllc config` prints")
      .def("nodes", [](const map::Map& mp, int frame) {
             if (frame < 0 || frame >= mp.size()) throw py::index_error("no frame " + std::to_string(frame));
             return nodesToArrays(mp.database.nodes(frame));
           },
           py::arg("frame"), "(centres (N, 3) float64, classes (N,) int32) of a map frame.")
      .def("save",
           [](const map::Map& mp, const std::string& path, bool force) {
             py::gil_scoped_release release;
             map::writeMapFile(path, mp, io::overwriteIf(force));
           },
           py::arg("path"), py::arg("force") = false,
           "Writes the map file atomically; an existing file raises sgtllc.Error unless force=True.");
  m.def("load_map",
        [](const std::string& path, const Config* config) {
          requireFile(path);
          py::gil_scoped_release release;
          return std::make_shared<map::Map>(config ? map::readMapFile(path, *config) : map::readMapFile(path));
        },
        py::arg("path"), py::arg("config") = py::none(),
        "Reads a map file (one sequential read). A truncated, corrupted, newer-version file, or (with config) one\n"
        "built with other map fields, raises sgtllc.Error naming the file and the problem.");

  py::class_<map::Relocalization>(m, "Relocalization", "Where a query frame is in a map.")
      .def_readonly("search", &map::Relocalization::search, "the candidates and their verification (FrameResult)")
      .def_readonly("map_frame", &map::Relocalization::map_frame, "best verified map frame, or -1")
      .def_readonly("localized", &map::Relocalization::localized, "the best candidate's score > sigma_4, or tracked")
      .def_readonly("score", &map::Relocalization::score, "score of the best candidate (0 if none)")
      .def_readonly("tracked", &map::Relocalization::tracked,
                    "accepted by a RelocalizationTracker's agreement with the track, not by sigma_4")
      .def_readonly("weak_rotation", &map::Relocalization::weak_rotation,
                    "the inlier centres lie nearly on a line, so the rotation is not fixed: not localized")
      .def_property_readonly("T_mapframe_query",
                             [](const map::Relocalization& r) { return matrixToArray(r.T_mapframe_query); },
                             "(4, 4): p_mapframe = T_mapframe_query @ p_query")
      .def_property_readonly("T_world_query",
                             [](const map::Relocalization& r) -> py::object {
                               if (!r.T_world_query) return py::none();
                               return matrixToArray(*r.T_world_query);
                             },
                             "(4, 4) pose of the query in the map's world frame, or None (no poses or candidate)");

  py::class_<PyRelocalizer>(m, "Relocalizer",
                            "Queries frames against a map: every map frame is eligible, nothing is inserted.")
      .def(py::init<const map::Map&, const Config&, int, double>(), py::arg("map"), py::arg("config") = Config{},
           py::arg("num_candidates") = map::RelocalizerOptions{}.num_candidates,
           py::arg("max_rotation_uncertainty_deg") = map::RelocalizerOptions{}.max_rotation_uncertainty_deg,
           "Raises sgtllc.Error if the map was built with other map fields than config's. num_candidates: "
           "shortlist per query (0 = config.retrieval.num_candidates). max_rotation_uncertainty_deg: accept an "
           "answer only if its rotation is fixed to within about this (0 = no check; below 90).")
      .def("localize",
           [](PyRelocalizer& r, const ArrayLike& points, const ArrayLike& labels, bool drop_nonfinite) {
             LabeledCloud cloud = cloudFromArrays(points, labels, "", drop_nonfinite);
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(r.mutex);
             return r.relocalizer.localize(cloud);
           },
           py::arg("points"), py::arg("labels"), py::arg("drop_nonfinite") = false,
           "A labelled scan (arrays as LoopDetector.process) against the map. Returns a Relocalization.")
      .def("localize_nodes",
           [](PyRelocalizer& r, const ArrayLike& centres, const ArrayLike& classes) {
             std::vector<Node> nodes =
                 nodesFromArrays(centres, classes, "", r.relocalizer.config().numClasses());
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(r.mutex);
             return r.relocalizer.localize(std::move(nodes));
           },
           py::arg("centres"), py::arg("classes"), "Ready-made nodes against the map. Returns a Relocalization.");

  py::class_<PyTracker>(m, "RelocalizationTracker",
                        "Relocalizes consecutive frames of one stream: a weaker verified answer is accepted when it "
                        "agrees with the last accepted one (docs/relocalization.md).")
      .def(py::init([](PyRelocalizer& r, double weak_sigma, double gate_m, double max_speed_m_per_frame, int window) {
             return std::make_unique<PyTracker>(r, map::TrackingOptions{weak_sigma, gate_m, max_speed_m_per_frame,
                                                                        window});
           }),
           py::arg("relocalizer"), py::arg("weak_sigma") = map::TrackingOptions{}.weak_sigma,
           py::arg("gate_m") = map::TrackingOptions{}.gate_m,
           py::arg("max_speed_m_per_frame") = map::TrackingOptions{}.max_speed_m_per_frame,
           py::arg("window") = map::TrackingOptions{}.window, py::keep_alive<1, 2>())
      .def("localize_nodes",
           [](PyTracker& t, const ArrayLike& centres, const ArrayLike& classes) {
             std::vector<Node> nodes =
                 nodesFromArrays(centres, classes, "", t.owner.relocalizer.config().numClasses());
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(t.owner.mutex);
             return t.tracker.localize(std::move(nodes));
           },
           py::arg("centres"), py::arg("classes"), "The next frame of the stream. Returns a Relocalization.")
      .def("reset", &PyTracker::reset_, "Forgets the track.");
}

}  // namespace sgtllc::python
