// Loop-closure and trajectory metrics (include/sgtllc/eval/metrics.h, trajectory_error.h), as `sgtllc eval` and
// `sgtllc optimize` compute them.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "opaque.h"
#include "sgtllc/eval/metrics.h"
#include "sgtllc/eval/trajectory_error.h"

namespace sgtllc::python {
namespace {

eval::PrCurve prCurve(const ArrayLike& scores, const ArrayLike& positives, int positives_override) {
  const std::vector<double> s = doublesFromArray(scores, "scores");
  const std::vector<double> p = doublesFromArray(positives, "positives");
  if (p.size() != s.size()) {
    throw py::value_error("positives: expected an (N,) bool array, N = " + std::to_string(s.size()) + " (one per score), got " +
                          std::to_string(p.size()));
  }
  std::vector<eval::ScoredSample> samples(s.size());
  for (size_t i = 0; i < s.size(); ++i) samples[i] = {s[i], p[i] != 0.0};
  return eval::precisionRecallCurve(std::move(samples), positives_override);
}

py::array_t<double> toArray(std::vector<double> v) {
  const auto n = static_cast<py::ssize_t>(v.size());
  return vectorToArray(std::move(v), {n});
}

void errorTypes(py::module_& m) {
  py::class_<eval::ErrorStats>(m, "ErrorStats", "Summary of a list of errors (all 0 for an empty list).")
      .def_readonly("rmse", &eval::ErrorStats::rmse, "root mean square")
      .def_readonly("mean", &eval::ErrorStats::mean)
      .def_readonly("median", &eval::ErrorStats::median, "as numpy: mean of the middle two for an even count")
      .def_readonly("max", &eval::ErrorStats::max)
      .def_readonly("count", &eval::ErrorStats::count, "errors summarised");
  py::class_<eval::AteResult>(m, "AteResult", "Absolute trajectory error (m), as evo_ape.")
      .def_readonly("aligned", &eval::AteResult::aligned, "after the rigid (Umeyama, no scale) alignment")
      .def_readonly("unaligned", &eval::AteResult::unaligned, "positions compared as given")
      .def_property_readonly("T_gt_est", [](const eval::AteResult& r) { return matrixToArray(r.T_gt_est.matrix()); },
                             "(4, 4) the alignment");
  py::class_<eval::RpeResult>(m, "RpeResult", "Relative pose error over a fixed frame step, as evo_rpe.")
      .def_readonly("delta_frames", &eval::RpeResult::delta_frames, "frame step D")
      .def_readonly("translation_m", &eval::RpeResult::translation_m, "ErrorStats of ‖t(E_i)‖ (m)")
      .def_readonly("rotation_deg", &eval::RpeResult::rotation_deg, "ErrorStats of angle(E_i) (deg)");
  py::class_<eval::SegmentError>(m, "SegmentError", "The KITTI odometry benchmark's segment error.")
      .def_readonly("translation_percent", &eval::SegmentError::translation_percent, "mean ‖t(E)‖ / length × 100")
      .def_readonly("rotation_deg_per_100m", &eval::SegmentError::rotation_deg_per_100m, "mean angle(E) / length")
      .def_readonly("segments", &eval::SegmentError::segments, "segments evaluated");
}

}  // namespace

void bindMetrics(py::module_& m) {
  py::class_<eval::PrCurve>(m, "PrCurve", "Precision-recall curve, one point per distinct threshold, as sklearn.")
      .def_property_readonly("thresholds", [](const eval::PrCurve& c) { return toArray(c.thresholds); }, "descending")
      .def_property_readonly("precision", [](const eval::PrCurve& c) { return toArray(c.precision); }, "per threshold, then 1")
      .def_property_readonly("recall", [](const eval::PrCurve& c) { return toArray(c.recall); }, "per threshold, then 0")
      .def_readonly("positives", &eval::PrCurve::positives, "the recall denominator");
  m.def("precision_recall", &prCurve, py::arg("scores"), py::arg("positives"), py::arg("positives_override") = 0,
        "PR curve of (N,) scores against (N,) ground-truth flags (a sample is positive iff score >= threshold);\n"
        "positives_override > 0 replaces the recall denominator (top-1 protocol).");
  m.def("f1_max", &eval::f1Max, py::arg("curve"), "max 2PR / (P + R) over the curve.");
  m.def("recall_at_100_precision", &eval::recallAt100Precision, py::arg("curve"),
        "Largest recall at precision exactly 1.");
  m.def("extended_precision", &eval::extendedPrecision, py::arg("curve"), "EP = (P_Rmin + R_P100) / 2 (algorithm §9).");

  py::class_<eval::PoseError>(m, "PoseError", "Relative pose error of an estimate against the ground truth.")
      .def(py::init([](double t, double r) { return eval::PoseError{t, r}; }), py::arg("translation_m") = 0.0,
           py::arg("rotation_deg") = 0.0)
      .def_readonly("translation_m", &eval::PoseError::translation_m, "RTE (m)")
      .def_readonly("rotation_deg", &eval::PoseError::rotation_deg, "RRE (deg)")
      .def("succeeds", &eval::PoseError::succeeds, py::arg("max_translation_m"), py::arg("max_rotation_deg"));
  m.def("pose_error",
        [](const ArrayLike& est, const ArrayLike& gt) {
          return eval::poseError(matrixFromArray(est, "estimate", 4, 4), matrixFromArray(gt, "ground_truth", 4, 4));
        },
        py::arg("estimate"), py::arg("ground_truth"), "RTE and RRE of a (4, 4) estimate against a (4, 4) ground truth.");
  py::class_<eval::PoseSummary>(m, "PoseSummary", "Success rate and mean errors over successes.")
      .def_readonly("evaluated", &eval::PoseSummary::evaluated, "loops with a pose compared")
      .def_readonly("successes", &eval::PoseSummary::successes, "RTE and RRE below the bounds")
      .def_readonly("success_rate", &eval::PoseSummary::success_rate, "successes / evaluated")
      .def_readonly("rte_mean", &eval::PoseSummary::rte_mean, "m")
      .def_readonly("rre_mean", &eval::PoseSummary::rre_mean, "deg");
  m.def("summarise_poses", &eval::summarisePoses, py::arg("errors"), py::arg("max_translation_m") = 2.0,
        py::arg("max_rotation_deg") = 5.0, "Success rate (RTE < max_translation_m and RRE < max_rotation_deg).");

  errorTypes(m);
  m.def("absolute_trajectory_error",
        [](const ArrayLike& gt, const ArrayLike& est) {
          return eval::absoluteTrajectoryError(isometriesFromArray(gt, "ground_truth"), isometriesFromArray(est, "estimate"));
        },
        py::arg("ground_truth"), py::arg("estimate"), "ATE of (N, 4, 4) poses against (N, 4, 4) ground truth.");
  m.def("relative_pose_error",
        [](const ArrayLike& gt, const ArrayLike& est, int delta) {
          return eval::relativePoseError(isometriesFromArray(gt, "ground_truth"), isometriesFromArray(est, "estimate"),
                                         delta);
        },
        py::arg("ground_truth"), py::arg("estimate"), py::arg("delta_frames") = 1, "RPE over pairs (i, i + delta).");
  m.def("kitti_segment_error",
        [](const ArrayLike& gt, const ArrayLike& est, std::vector<double> lengths, int step) {
          return eval::kittiSegmentError(isometriesFromArray(gt, "ground_truth"), isometriesFromArray(est, "estimate"),
                                         lengths, step);
        },
        py::arg("ground_truth"), py::arg("estimate"),
        py::arg("lengths_m") = std::vector<double>{100, 200, 300, 400, 500, 600, 700, 800}, py::arg("step_frames") = 10,
        "The KITTI devkit's segment error (translation %, rotation deg / 100 m).");
}

}  // namespace sgtllc::python
