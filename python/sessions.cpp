// SessionPipeline (include/sgtllc/pipeline/session_pipeline.h): a new session run against a saved map and merged
// into its frame, as `sgtllc run --map` does (docs/sessions.md). The pipeline runs with the GIL released, behind its
// own lock.
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "sgtllc/pipeline/session_pipeline.h"

namespace sgtllc::python {
namespace {

struct PySession {
  PySession(const map::Map& m, const Config& config, pipeline::SessionOptions options)
      : pipeline(copyMap(m), config, std::move(options)) {}
  pipeline::SessionPipeline pipeline;
  std::mutex mutex;
};

/// What one frame brought (the C++ result's intra-session part without its re-solve, which a session has not).
struct PySessionFrame {
  int index = -1;
  FrameResult detection;
  std::optional<pipeline::ClosingLoop> loop;
  map::Relocalization in_map;
  std::optional<pipeline::ClosingLoop> inter;
};

PySessionFrame copied(pipeline::SessionFrame f) {
  return {f.own.index, std::move(f.own.detection), std::move(f.own.loop), std::move(f.in_map), std::move(f.inter)};
}

}  // namespace

void bindSessions(py::module_& m) {
  py::class_<backend::SessionMerge>(m, "SessionMerge", "What the merge made of a session (backend/session_merge.h).")
      .def_readonly("result", &backend::SessionMerge::result,
                    "BackendResult: each loop's decision (SessionPipeline.loops order), the session's poses")
      .def_readonly("placed", &backend::SessionMerge::placed,
                    "enough consistent inter-session loops were accepted: the session is in the map's frame")
      .def_readonly("inter_loops", &backend::SessionMerge::inter_loops, "inter-session loops found")
      .def_readonly("inter_accepted", &backend::SessionMerge::inter_accepted, "of them accepted")
      .def_property_readonly("T_world_odometry",
                             [](const backend::SessionMerge& s) { return matrixToArray(s.T_world_odometry.matrix()); },
                             "(4, 4) the session's odometry frame in the map's world the solve started from");
  py::class_<pipeline::SessionClosing>(m, "SessionClosing", "The merge of a session (SessionPipeline.finish).")
      .def_readonly("merge", &pipeline::SessionClosing::merge, "SessionMerge")
      .def_readonly("ms", &pipeline::SessionClosing::ms, "the merge's time (ms)");
  py::class_<PySessionFrame>(m, "SessionFrame", "What one frame brought to a SessionPipeline.")
      .def_readonly("index", &PySessionFrame::index, "the frame's number in the session, 0, 1, 2, ...")
      .def_readonly("detection", &PySessionFrame::detection, "FrameResult of the search among the session's frames")
      .def_readonly("loop", &PySessionFrame::loop, "the intra-session ClosingLoop found at this frame, or None")
      .def_readonly("in_map", &PySessionFrame::in_map, "Relocalization: the frame searched in the map")
      .def_readonly("inter", &PySessionFrame::inter, "the inter-session ClosingLoop it gave, or None");

  py::class_<PySession>(m, "SessionPipeline",
                        "A new session run against a saved map (docs/sessions.md): every frame is searched in the map\n"
                        "and among the session's own frames; finish() places the session in the map's frame with the\n"
                        "map's poses fixed, and merged_map() is the map with the session appended.")
      .def(py::init([](const map::Map& mp, const Config& config, std::string name, std::string map_session) {
             return std::make_unique<PySession>(mp, config, pipeline::SessionOptions{std::move(name), std::move(map_session)});
           }),
           py::arg("map"), py::arg("config") = Config{}, py::arg("name") = "session", py::arg("map_session") = "map",
           "map: a Map with poses; name: the session's name (its frames are NAME/FRAME in the merged map);\n"
           "map_session: the name the map's frames get when the map has no sessions yet. Raises sgtllc.Error for\n"
           "a map without poses or of another configuration, or a name that is empty, holds '/' or is taken.")
      .def("add_scan",
           [](PySession& p, const ArrayLike& points, const py::object& labels, const ArrayLike& pose, std::string name,
              bool drop_nonfinite) {
             LabeledCloud cloud;
             if (labels.is_none()) {
               cloud.points = pointsFromArray(points, "points", drop_nonfinite);
             } else {
               cloud = cloudFromArrays(points, labels, "", drop_nonfinite);
             }
             const Eigen::Isometry3d T = isometryFromArray(pose, "pose");
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(p.mutex);
             return copied(p.pipeline.addScan(cloud, T, std::move(name)));
           },
           py::arg("points"), py::arg("labels") = py::none(), py::kw_only(), py::arg("pose"), py::arg("name") = "",
           py::arg("drop_nonfinite") = false,
           "A scan as LoopClosingPipeline.add_scan takes it; pose (4, 4): the session's odometry pose, in its own\n"
           "frame. Returns a SessionFrame.")
      .def("add_nodes",
           [](PySession& p, const ArrayLike& centres, const ArrayLike& classes, const ArrayLike& pose, std::string name) {
             std::vector<Node> nodes =
                 nodesFromArrays(centres, classes, "", p.pipeline.session().config().numClasses());
             const Eigen::Isometry3d T = isometryFromArray(pose, "pose");
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(p.mutex);
             return copied(p.pipeline.addNodes(std::move(nodes), T, std::move(name)));
           },
           py::arg("centres"), py::arg("classes"), py::arg("pose"), py::arg("name") = "",
           "A frame as ready-made nodes: centres (N, 3), classes (N,) stable class indices; as add_scan.")
      .def("add_loop",
           [](PySession& p, const backend::Edge& edge, std::string query, std::string match, bool injected) {
             pipeline::ClosingLoop l;
             l.edge = edge;
             l.edge.kind = backend::EdgeKind::kLoop;
             l.query = std::move(query);
             l.match = std::move(match);
             l.injected = injected;
             std::lock_guard<std::mutex> lock(p.mutex);
             p.pipeline.addLoop(std::move(l));
           },
           py::arg("edge"), py::arg("query") = "", py::arg("match") = "", py::kw_only(), py::arg("injected") = false,
           "A loop found elsewhere, merged at finish() and judged like the detected ones: edge.from_ a map frame\n"
           "(0..M-1) or a session frame M + i, edge.to a session frame M + j, both already added; injected marks a\n"
           "robustness test's false loop (as `sgtllc run --map --add-false-loops`). Raises sgtllc.Error after\n"
           "finish(), for frames out of range or between two map frames.")
      .def("finish",
           [](PySession& p) {
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(p.mutex);
             return p.pipeline.finish();
           },
           "Ends the session: the merge of every loop. Returns a SessionClosing; later frames raise sgtllc.Error.")
      .def_property_readonly("poses", [](PySession& p) { return posesToArray(p.pipeline.poses()); },
                             "(N, 4, 4) the session's poses: after finish() in the map's world if placed, before it\n"
                             "the odometry")
      .def_property_readonly("loops", [](PySession& p) { return p.pipeline.loops(); },
                             "inter- and intra-session ClosingLoops in the order found (map frames 0..M-1, session\n"
                             "frame i is M + i)")
      .def_property_readonly("map_frames", [](PySession& p) { return p.pipeline.mapFrames(); })
      .def_property_readonly("num_frames", [](PySession& p) { return p.pipeline.session().numFrames(); })
      .def("merged_map",
           [](PySession& p) {
             std::lock_guard<std::mutex> lock(p.mutex);
             return std::make_shared<map::Map>(p.pipeline.mergedMap());
           },
           "The map with the session appended (a Map to save or to merge the next session into). Raises\n"
           "sgtllc.Error before finish() or if the session was not placed.");
}

}  // namespace sgtllc::python
