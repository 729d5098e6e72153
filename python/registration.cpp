// Fine registration (include/sgtllc/registration/): its settings (registration.*) and the Refinement that
// PairResult and Candidate carry. Adding a field is one line here and one in sgtllc.pyi.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "sgtllc/registration/icp.h"
#include "sgtllc/config/registration_config.h"

namespace sgtllc::python {

void bindRegistration(py::module_& m) {
  py::enum_<RefinementStatus>(m, "RefinementStatus", "Outcome of a fine registration.")
      .value("CONVERGED", RefinementStatus::kConverged, "an update below registration.convergence; checks passed")
      .value("MAX_ITERATIONS", RefinementStatus::kMaxIterations, "max_iterations reached; checks passed")
      .value("TOO_FEW_POINTS", RefinementStatus::kTooFewPoints, "fewer than 6 points or pairs: nothing to fit")
      .value("DEGENERATE", RefinementStatus::kDegenerate, "the pairs leave a direction unconstrained")
      .value("LOW_FITNESS", RefinementStatus::kLowFitness, "too few paired points at the end: too little overlap")
      .value("MOVED_TOO_FAR", RefinementStatus::kMovedTooFar, "moved the seed beyond the bounds: diverged");

  using R = RegistrationConfig;
  py::class_<R>(m, "RegistrationConfig", "Fine registration of loop poses (registration.*).")
      .def(py::init<>())
      .def_readwrite("pair", &R::pair, "refine compare_pair's pose (labelled scans only)")
      .def_readwrite("online", &R::online, "refine the online detector's declared loop; keeps a cloud per frame")
      // A tuple, as ExtraClass.ids: `ground_ids.append(…)` would change a copy; assign a new list instead.
      .def_property("ground_ids", [](const R& r) { return py::tuple(py::cast(r.ground_ids)); },
                    [](R& r, std::vector<uint32_t> ids) { r.ground_ids = std::move(ids); },
                    "raw ids (0..65535) whose points also join the registration: the ground")
      .def_readwrite("voxel", &R::voxel, "voxel leaf of the query points (m)")
      .def_readwrite("max_points", &R::max_points, "most query points kept")
      .def_readwrite("match_voxel", &R::match_voxel, "voxel leaf of the match points (m)")
      .def_readwrite("match_max_points", &R::match_max_points, "most match points kept")
      .def_readwrite("normal_neighbors", &R::normal_neighbors, "neighbours whose covariance gives a normal")
      .def_readwrite("max_correspondence", &R::max_correspondence, "pairing distance (m)")
      .def_readwrite("coarse_correspondence", &R::coarse_correspondence,
                     "pairing distance of a first, coarse ICP stage (m); 0 = none")
      .def_readwrite("kernel", &R::kernel, "Cauchy scale on residuals (m); 0 = unweighted")
      .def_readwrite("max_iterations", &R::max_iterations, "Gauss-Newton iterations at most")
      .def_readwrite("convergence", &R::convergence, "converged once an update is below this (m, rad)")
      .def_readwrite("min_fitness", &R::min_fitness, "below this share of paired points the SVD pose is kept")
      .def_readwrite("max_translation_change", &R::max_translation_change, "largest accepted move (m)")
      .def_readwrite("max_rotation_change_deg", &R::max_rotation_change_deg, "largest accepted turn (degrees)")
      .def_readwrite("information_sigma_min", &R::information_sigma_min, "floor of the residual σ (m)")
      .def_readwrite("information_scale", &R::information_scale, "scales the information down (< 1)");

  py::class_<Refinement>(m, "Refinement", "Point-to-plane ICP of the query scan onto the match scan.")
      .def_readonly("status", &Refinement::status, "RefinementStatus")
      .def_property_readonly("used", &Refinement::used, "whether the refined pose replaced the seed")
      .def_property_readonly("T_match_query_seed", [](const Refinement& r) { return matrixToArray(r.T_match_query_seed); },
                             "(4, 4) the seed: the object-level SVD pose")
      .def_property_readonly("T_match_query", [](const Refinement& r) { return matrixToArray(r.T_match_query); },
                             "(4, 4) the refined pose if used, else the seed")
      .def_readonly("iterations", &Refinement::iterations, "Gauss-Newton steps taken")
      .def_readonly("fitness", &Refinement::fitness, "share of query points paired at the final pose")
      .def_readonly("rmse_m", &Refinement::rmse_m, "RMS point-to-plane distance of the pairs (m)")
      .def_readonly("query_points", &Refinement::query_points, "points of the query (source) cloud")
      .def_readonly("match_points", &Refinement::match_points, "points of the match (target) cloud")
      .def_property_readonly("information", [](const Refinement& r) { return Eigen::MatrixXd(r.information); },
                             "(6, 6) information over (δt m, δθ rad), back-end convention; zero unless used")
      .def_readonly("time_ms", &Refinement::time_ms, "wall-clock time of the refinement (ms)");
}

}  // namespace sgtllc::python
