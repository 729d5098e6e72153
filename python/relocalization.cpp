// The relocalization protocol's metrics (include/sgtllc/eval/relocalization.h, docs/relocalization.md).
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "sgtllc/eval/relocalization.h"

namespace sgtllc::python {

void bindRelocalization(py::module_& m) {
  using eval::RelocalizationQuery;
  py::class_<RelocalizationQuery>(m, "RelocalizationQuery", "What a relocalization returned for one query frame.")
      .def(py::init([](long query_number, int map_frame, bool accepted, double score, const py::object& T) {
             RelocalizationQuery q;
             q.query_number = query_number;
             q.map_frame = map_frame;
             q.accepted = accepted;
             q.score = score;
             if (!T.is_none()) q.T_mapframe_query = isometryFromArray(T, "T_mapframe_query");
             return q;
           }),
           py::arg("query_number"), py::arg("map_frame") = -1, py::arg("accepted") = false, py::arg("score") = 0.0,
           py::arg("T_mapframe_query") = py::none())
      .def_readwrite("query_number", &RelocalizationQuery::query_number, "frame number in the query sequence")
      .def_readwrite("map_frame", &RelocalizationQuery::map_frame, "map frame returned; -1 = none")
      .def_readwrite("accepted", &RelocalizationQuery::accepted, "passed the gates")
      .def_readwrite("score", &RelocalizationQuery::score, "reported, not used by the metrics")
      .def_property(
          "T_mapframe_query", [](const RelocalizationQuery& q) { return matrixToArray(q.T_mapframe_query.matrix()); },
          [](RelocalizationQuery& q, const py::object& T) {
            q.T_mapframe_query = isometryFromArray(T, "T_mapframe_query");
          },
          "(4, 4) maps query points into the returned map frame");
  using eval::RelocalizationProtocol;
  py::class_<RelocalizationProtocol>(m, "RelocalizationProtocol", "The protocol's thresholds.")
      .def(py::init<>())
      .def_readwrite("positive_distance", &RelocalizationProtocol::positive_distance, "m (default 3)")
      .def_readwrite("negative_distance", &RelocalizationProtocol::negative_distance, "m (default 20)")
      .def_readwrite("max_translation_m", &RelocalizationProtocol::max_translation_m, "pose success: RTE below (2)")
      .def_readwrite("max_rotation_deg", &RelocalizationProtocol::max_rotation_deg, "pose success: RRE below (5)");
  using eval::RelocalizationMetrics;
  py::class_<RelocalizationMetrics>(m, "RelocalizationMetrics", "Ratios (None when n/a) and the counts behind them.")
      .def_readonly("queries", &RelocalizationMetrics::queries)
      .def_readonly("positives", &RelocalizationMetrics::positives, "a map frame within 3 m")
      .def_readonly("negatives", &RelocalizationMetrics::negatives, "no map frame within 20 m")
      .def_readonly("accepted", &RelocalizationMetrics::accepted)
      .def_readonly("accepted_near", &RelocalizationMetrics::accepted_near, "returned frame within 3 m: correct")
      .def_readonly("accepted_between", &RelocalizationMetrics::accepted_between, "returned frame 3-20 m away")
      .def_readonly("accepted_far", &RelocalizationMetrics::accepted_far, "returned frame beyond 20 m")
      .def_readonly("accepted_negatives", &RelocalizationMetrics::accepted_negatives, "false relocalizations")
      .def_readonly("pose_successes", &RelocalizationMetrics::pose_successes, "correct with RTE < 2 m, RRE < 5 deg")
      .def_readonly("recall_at_1", &RelocalizationMetrics::recall_at_1, "accepted_near / positives")
      .def_readonly("precision", &RelocalizationMetrics::precision, "accepted_near / accepted")
      .def_readonly("precision_no_between", &RelocalizationMetrics::precision_no_between,
                    "accepted_near / (accepted - accepted_between)")
      .def_readonly("pose_success", &RelocalizationMetrics::pose_success, "pose_successes / accepted_near")
      .def_readonly("rte_mean_m", &RelocalizationMetrics::rte_mean_m, "over the pose successes")
      .def_readonly("rre_mean_deg", &RelocalizationMetrics::rre_mean_deg, "over the pose successes")
      .def_readonly("false_rate", &RelocalizationMetrics::false_rate, "accepted_negatives / negatives")
      .def_readonly("accepted_placed", &RelocalizationMetrics::accepted_placed,
                    "accepted with the estimated pose within RTE < 2 m, RRE < 5 deg of the truth")
      .def_readonly("positives_placed", &RelocalizationMetrics::positives_placed, "accepted_placed of positives")
      .def_readonly("precision_pose", &RelocalizationMetrics::precision_pose, "accepted_placed / accepted")
      .def_readonly("recall_at_1_pose", &RelocalizationMetrics::recall_at_1_pose, "positives_placed / positives");
  m.def("relocalization_metrics",
        [](const std::vector<RelocalizationQuery>& queries, const ArrayLike& map_poses, const ArrayLike& query_poses,
           const RelocalizationProtocol& protocol) {
          return eval::relocalizationMetrics(queries, isometriesFromArray(map_poses, "map_poses"),
                                             isometriesFromArray(query_poses, "query_poses"), protocol);
        },
        py::arg("queries"), py::arg("map_poses"), py::arg("query_poses"),
        py::arg("protocol") = RelocalizationProtocol(),
        "The relocalization protocol (docs/relocalization.md): queries against (M, 4, 4) map and (N, 4, 4) query\n"
        "poses T_world_lidar in one world frame.");
}

}  // namespace sgtllc::python
