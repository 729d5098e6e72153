// Fine registration (include/sgtllc/registration/): its settings (registration.*) and the Refinement that
// PairResult and Candidate carry. The settings are properties made from
// the settings table (settings.h).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "settings.h"
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
  settingsClass<R>(m, "RegistrationConfig", "Fine registration of loop poses (registration.*).")
      .def(py::init<>());

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
