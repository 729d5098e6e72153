// LoopClosingPipeline (include/sgtllc/pipeline/loop_closing_pipeline.h): frames in with their odometry poses, loops
// and the corrected trajectory out, as `sgtllc run` does. Arrays are converted with the GIL held; the pipeline
// itself runs with the GIL released, behind the pipeline's own lock (it is not thread-safe).
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "sgtllc/pipeline/loop_closing_pipeline.h"

namespace sgtllc::python {
namespace {

struct PyPipeline {
  PyPipeline(const Config& config, pipeline::PipelineOptions options) : pipeline(config, options) {}
  pipeline::LoopClosingPipeline pipeline;
  std::mutex mutex;
};

/// What one frame brought, with the re-solve's result copied (the C++ one is valid until the next call only).
struct PyPipelineFrame {
  int index = -1;
  FrameResult detection;
  std::optional<pipeline::ClosingLoop> loop;
  bool solved = false;
  std::optional<backend::BackendResult> update;
  double solve_ms = 0.0;
};

PyPipelineFrame copied(pipeline::PipelineFrame f) {
  PyPipelineFrame out{f.index, std::move(f.detection), std::move(f.loop), f.solved, std::nullopt, f.solve_ms};
  if (f.update) out.update = *f.update;
  return out;
}

std::optional<Eigen::Isometry3d> poseOf(const py::object& pose) {
  if (pose.is_none()) return std::nullopt;
  return isometryFromArray(pose, "pose");
}

}  // namespace

void bindPipeline(py::module_& m) {
  py::class_<pipeline::ClosingLoop>(m, "ClosingLoop", "A loop as an edge of the pose graph, with its frame names.")
      .def_readonly("edge", &pipeline::ClosingLoop::edge, "Edge: from_ = match frame, to = query frame")
      .def_readonly("query", &pipeline::ClosingLoop::query, "the query frame's name")
      .def_readonly("match", &pipeline::ClosingLoop::match, "the matched (older) frame's name")
      .def_property_readonly("T_match_query",
                             [](const pipeline::ClosingLoop& l) { return matrixToArray(l.edge.T_from_to.matrix()); },
                             "(4, 4) pose of the query frame in the match frame")
      .def_readonly("score", &pipeline::ClosingLoop::score, "the loop score")
      .def_readonly("score_c", &pipeline::ClosingLoop::score_c, "the consistency score")
      .def_readonly("injected", &pipeline::ClosingLoop::injected, "a robustness test's false loop, not a detected one")
      .def_readonly("has_information", &pipeline::ClosingLoop::has_information,
                    "False: collinear inlier centres, the nominal information is used")
      .def("__repr__", [](const pipeline::ClosingLoop& l) {
        return "<ClosingLoop " + l.query + " -> " + l.match + " score " + std::to_string(l.score) + ">";
      });
  py::class_<pipeline::Closing>(m, "Closing", "What the back end made of a drive's loops (LoopClosingPipeline.finish).")
      .def_readonly("result", &pipeline::Closing::result, "BackendResult: each loop's decision, solver statistics")
      .def_property_readonly("poses", [](const pipeline::Closing& c) { return posesToArray(c.poses); },
                             "(N, 4, 4) corrected trajectory T_world_frame")
      .def_readonly("ms", &pipeline::Closing::ms, "optimisation time, all solves (ms)")
      .def_readonly("final_ms", &pipeline::Closing::final_ms, "online: the final full solve (ms)")
      .def_readonly("online_solve_cpu_ms", &pipeline::Closing::online_solve_cpu_ms,
                    "online: CPU time of each re-solve at a loop (ms)")
      .def_readonly("online_final_shift_m", &pipeline::Closing::online_final_shift_m,
                    "online: how far the final full solve moved each frame (m)");
  py::class_<PyPipelineFrame>(m, "PipelineFrame", "What one frame brought to a LoopClosingPipeline.")
      .def_readonly("index", &PyPipelineFrame::index, "the frame's number, 0, 1, 2, ... in the order given")
      .def_readonly("detection", &PyPipelineFrame::detection, "FrameResult: candidates, verification, timing")
      .def_readonly("loop", &PyPipelineFrame::loop, "the ClosingLoop found at this frame, or None")
      .def_readonly("solved", &PyPipelineFrame::solved, "online: the graph was re-solved; poses moved")
      .def_readonly("update", &PyPipelineFrame::update, "that re-solve's BackendResult, or None")
      .def_readonly("solve_ms", &PyPipelineFrame::solve_ms, "wall time of the re-solve (ms)");

  py::class_<PyPipeline>(m, "LoopClosingPipeline",
                         "Loop closing as a SLAM system embeds it (docs/pipeline.md): frames in one at a time with\n"
                         "their odometry poses (or none: detection only), loops and the corrected trajectory out.")
      .def(py::init([](const Config& config, bool online, int accumulate) {
             return std::make_unique<PyPipeline>(config, pipeline::PipelineOptions{online, accumulate});
           }),
           py::arg("config") = Config{}, py::arg("online") = false, py::arg("accumulate") = 1,
           "online: re-solve the pose graph at every loop (else once, at finish()); accumulate: scans merged into\n"
           "each frame by their poses (1 = off). Raises ConfigError or sgtllc.Error for invalid settings.")
      .def("add_scan",
           [](PyPipeline& p, const ArrayLike& points, const py::object& labels, const py::object& pose,
              std::string name, bool drop_nonfinite) {
             LabeledCloud cloud;
             if (labels.is_none()) {
               cloud.points = pointsFromArray(points, "points", drop_nonfinite);
             } else {
               cloud = cloudFromArrays(points, labels, "", drop_nonfinite);
             }
             const std::optional<Eigen::Isometry3d> T = poseOf(pose);
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(p.mutex);
             return copied(p.pipeline.addScan(cloud, T, std::move(name)));
           },
           py::arg("points"), py::arg("labels") = py::none(), py::arg("pose") = py::none(), py::arg("name") = "",
           py::arg("drop_nonfinite") = false,
           "A scan: points (N, 3) or (N, 4) float in the sensor frame, labels (N,) raw ids (None with\n"
           "labeller.source geometric), pose (4, 4) T_world_frame from the odometry (with every frame or none),\n"
           "name (default: the index, six digits). Returns a PipelineFrame.")
      .def("add_nodes",
           [](PyPipeline& p, const ArrayLike& centres, const ArrayLike& classes, const py::object& pose,
              std::string name) {
             std::vector<Node> nodes = nodesFromArrays(centres, classes, "", p.pipeline.config().numClasses());
             const std::optional<Eigen::Isometry3d> T = poseOf(pose);
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(p.mutex);
             return copied(p.pipeline.addNodes(std::move(nodes), T, std::move(name)));
           },
           py::arg("centres"), py::arg("classes"), py::arg("pose") = py::none(), py::arg("name") = "",
           "A frame as ready-made nodes: centres (N, 3) float, classes (N,) stable class indices; as add_scan.")
      .def("finish",
           [](PyPipeline& p) {
             py::gil_scoped_release release;
             std::lock_guard<std::mutex> lock(p.mutex);
             return p.pipeline.finish();
           },
           "Ends the drive: the batch solve, or online the final full solve. Needs the frames' poses. Returns a\n"
           "Closing; later frames raise sgtllc.Error.")
      .def_property_readonly("poses", [](PyPipeline& p) { return posesToArray(p.pipeline.poses()); },
                             "(N, 4, 4) best poses now: after finish() the final solution, online the last\n"
                             "re-solve's (frames after it dead-reckoned), otherwise the odometry")
      .def_property_readonly("odometry", [](PyPipeline& p) { return posesToArray(p.pipeline.odometry()); },
                             "(N, 4, 4) the odometry poses as given, rotations orthonormalised")
      .def_property_readonly("loops", [](PyPipeline& p) { return p.pipeline.loops(); },
                             "every ClosingLoop found so far, in the order found")
      .def_property_readonly("names", [](PyPipeline& p) { return p.pipeline.names(); }, "the frames' names")
      .def_property_readonly("num_frames", [](PyPipeline& p) { return p.pipeline.numFrames(); })
      .def_property_readonly("config", [](PyPipeline& p) { return p.pipeline.config(); }, "a copy of the config")
      .def("to_map",
           [](PyPipeline& p, const py::object& poses) {
             std::optional<std::vector<Eigen::Matrix4d>> placed;
             if (!poses.is_none()) placed = rigidPosesFromArray(poses, "poses");
             std::lock_guard<std::mutex> lock(p.mutex);
             return std::make_shared<map::Map>(p.pipeline.map(std::move(placed)));
           },
           py::arg("poses") = py::none(),
           "The frames as a Map (for relocalization), placed by poses (N, 4, 4) or, by default, by the pipeline's\n"
           "poses when the frames had any.");
}

}  // namespace sgtllc::python
