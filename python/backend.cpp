// The pose-graph back end (include/sgtllc/backend/): odometry and loop edges, the outlier step, batch and online
// optimisation. Poses are (4, 4) float64 arrays T_world_frame; an edge's T_from_to maps `to` points into `from`.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "opaque.h"
#include "sgtllc/backend/information.h"
#include "sgtllc/backend/pose_graph_optimizer.h"

namespace sgtllc::python {
namespace {

using backend::BackendResult;
using backend::Edge;
using backend::PoseGraphOptimizer;

std::vector<Node> nodesArg(const py::tuple& t, const char* name) {
  if (t.size() != 2) throw py::value_error(std::string(name) + ": expected a (centres, classes) tuple");
  return nodesFromArrays(t[0], t[1], std::string(name) + "_", kMaxClasses);
}

void resultTypes(py::module_& m) {
  py::enum_<backend::LoopDecision>(m, "LoopDecision", "What the outlier step decided about a loop.")
      .value("ACCEPTED", backend::LoopDecision::kAccepted, "used by the optimisation")
      .value("INCONSISTENT", backend::LoopDecision::kInconsistent, "outside the largest consistent set")
      .value("LARGE_RESIDUAL", backend::LoopDecision::kLargeResidual, "χ² after optimising above max_loop_chi2");
  py::class_<backend::LoopReport>(m, "LoopReport", "The back end's verdict on one loop.")
      .def_readonly("from_", &backend::LoopReport::from, "match frame")
      .def_readonly("to", &backend::LoopReport::to, "query frame")
      .def_readonly("decision", &backend::LoopReport::decision)
      .def_readonly("consistent_with", &backend::LoopReport::consistent_with, "loops it is pairwise consistent with")
      .def_readonly("chi2", &backend::LoopReport::chi2, "eᵀΩe at the returned poses");
  py::class_<BackendResult>(m, "BackendResult", "Result of an optimisation.")
      .def_property_readonly("poses", [](const BackendResult& r) { return posesToArray(r.poses); },
                             "(N, 4, 4) T_world_frame")
      .def_readonly("loops", &BackendResult::loops, "one LoopReport per loop, in the order received")
      .def_readonly("num_accepted", &BackendResult::num_accepted, "loops used by the optimisation")
      .def_readonly("num_rejected", &BackendResult::num_rejected, "inconsistent + large residual")
      .def_readonly("solves", &BackendResult::solves, "Ceres solves")
      .def_readonly("iterations", &BackendResult::iterations, "trust-region (Dogleg) iterations over all solves")
      .def_readonly("final_cost", &BackendResult::final_cost, "½ Σ ρ(eᵀΩe) of the last solve")
      .def_readonly("converged", &BackendResult::converged, "every solve met a tolerance")
      .def_readonly("reduced", &BackendResult::reduced, "from optimize_reduced: the anchors' graph")
      .def_readonly("num_poses_solved", &BackendResult::num_poses_solved, "poses in the last solve");
}

}  // namespace

void bindBackend(py::module_& m) {
  py::enum_<backend::EdgeKind>(m, "EdgeKind", "What produced a constraint.")
      .value("ODOMETRY", backend::EdgeKind::kOdometry)
      .value("LOOP", backend::EdgeKind::kLoop);
  py::class_<Edge>(m, "Edge", "A relative-pose constraint: p_from = T_from_to @ p_to.")
      .def(py::init([](int from, int to, const ArrayLike& T, const py::object& information, backend::EdgeKind kind) {
             Edge e{from, to, isometryFromArray(T, "T_from_to"), backend::Matrix6d::Identity(), kind};
             if (!information.is_none()) e.information = matrixFromArray(information, "information", 6, 6);
             return e;
           }),
           py::arg("from_"), py::arg("to"), py::arg("T_from_to"), py::arg("information") = py::none(),
           py::arg("kind") = backend::EdgeKind::kLoop)
      .def_readwrite("from_", &Edge::from, "frame whose coordinates the edge maps into (a loop's match frame)")
      .def_readwrite("to", &Edge::to, "the other frame (a loop's query frame)")
      .def_property("T_from_to", [](const Edge& e) { return matrixToArray(e.T_from_to.matrix()); },
                    [](Edge& e, const ArrayLike& T) { e.T_from_to = isometryFromArray(T, "T_from_to"); }, "(4, 4)")
      .def_readwrite("information", &Edge::information, "(6, 6) over (δt, δθ)")
      .def_readwrite("kind", &Edge::kind, "odometry or loop");
  resultTypes(m);

  m.def("odometry_information",
        [](const ArrayLike& T, const backend::OdometryNoise& noise) {
          return backend::odometryInformation(isometryFromArray(T, "T_prev_curr"), noise);
        },
        py::arg("T_prev_curr"), py::arg("noise") = backend::OdometryNoise{}, "(6, 6) information of an odometry step.");
  m.def("loop_edge",
        [](int match_frame, int query_frame, const MatchResult& match, const py::tuple& query_nodes,
           const py::tuple& match_nodes, const backend::LoopNoise& noise) {
          return backend::loopEdge(match_frame, query_frame, match, nodesArg(query_nodes, "query_nodes"),
                                   nodesArg(match_nodes, "match_nodes"), noise);
        },
        py::arg("match_frame"), py::arg("query_frame"), py::arg("match"), py::arg("query_nodes"),
        py::arg("match_nodes"), py::arg("noise") = backend::LoopNoise{},
        "The loop edge of a verified match with its information from the inlier centres (what `sgtllc run`\n"
        "writes); nodes as (centres, classes) tuples, e.g. LoopDetector.nodes(frame). Raises sgtllc.Error for\n"
        "fewer than 3 inliers or collinear inlier centres.");

  py::class_<PoseGraphOptimizer>(m, "PoseGraphOptimizer",
                                 "A growing pose graph: add_odometry per frame, close_loop when a loop arrives,\n"
                                 "optimize for the full (batch) solution. Frame 0 is fixed.")
      .def(py::init([](const backend::BackendConfig& config, const py::object& first) {
             const Eigen::Isometry3d T = first.is_none() ? Eigen::Isometry3d::Identity()
                                                         : isometryFromArray(first, "T_world_first");
             return std::make_unique<PoseGraphOptimizer>(config, T);
           }),
           py::arg("config") = backend::BackendConfig{}, py::arg("T_world_first") = py::none())
      .def("add_odometry",
           [](PoseGraphOptimizer& o, const ArrayLike& T, const py::object& information) {
             const Eigen::Isometry3d step = isometryFromArray(T, "T_prev_curr");
             if (information.is_none()) return o.addOdometry(step);
             return o.addOdometry(step, matrixFromArray(information, "information", 6, 6));
           },
           py::arg("T_prev_curr"), py::arg("information") = py::none(), "Adds the next frame; returns its index.")
      .def("add_loop", &PoseGraphOptimizer::addLoop, py::arg("loop"), "Records a loop edge without optimising.")
      .def("close_loop", &PoseGraphOptimizer::closeLoop, py::arg("loop"), py::call_guard<py::gil_scoped_release>(),
           py::return_value_policy::copy, "add_loop, then the online re-optimisation.")
      .def("optimize", &PoseGraphOptimizer::optimize, py::call_guard<py::gil_scoped_release>(),
           py::return_value_policy::copy, "Outlier step and optimisation of the full graph.")
      .def("optimize_reduced", &PoseGraphOptimizer::optimizeReduced, py::call_guard<py::gil_scoped_release>(),
           py::return_value_policy::copy, "The same on the reduced graph of the anchors.")
      .def_property_readonly("num_frames", &PoseGraphOptimizer::numFrames, "frames added")
      .def_property_readonly("num_loops", &PoseGraphOptimizer::numLoops, "loops received")
      .def_property_readonly("poses", [](const PoseGraphOptimizer& o) { return posesToArray(o.poses()); },
                             "(N, 4, 4) current estimate T_world_frame")
      .def_property_readonly("result", [](const PoseGraphOptimizer& o) { return o.result(); }, "last optimisation");
}

}  // namespace sgtllc::python
