// BackendConfig and its sections, field by field as in include/sgtllc/config/backend_config.h (units and the
// model behind each group are documented there and in docs/backend.md).
#include "bindings.h"
#include "opaque.h"
#include "sgtllc/config/backend_config.h"

namespace sgtllc::python {

void bindBackendConfig(py::module_& m) {
  using namespace sgtllc::backend;
  py::enum_<RobustLoss>(m, "RobustLoss", "Robust loss on loop edges (backend.loop_loss).")
      .value("NONE", RobustLoss::kNone, "plain least squares")
      .value("HUBER", RobustLoss::kHuber, "quadratic below loss_scale, linear above")
      .value("CAUCHY", RobustLoss::kCauchy, "a² log(1 + s²/a²) (default)");

  py::class_<OdometryNoise>(m, "OdometryNoise", "Odometry information model (backend.odometry.*).")
      .def(py::init<>())
      .def_readwrite("translation_sigma_per_m", &OdometryNoise::translation_sigma_per_m, "translation σ per metre (m/m)")
      .def_readwrite("translation_sigma_min", &OdometryNoise::translation_sigma_min, "translation σ floor (m)")
      .def_readwrite("rotation_sigma_per_m", &OdometryNoise::rotation_sigma_per_m, "rotation σ per metre (rad/m)")
      .def_readwrite("rotation_sigma_per_rad", &OdometryNoise::rotation_sigma_per_rad, "rotation σ per radian (rad/rad)")
      .def_readwrite("rotation_sigma_min", &OdometryNoise::rotation_sigma_min, "rotation σ floor (rad)");

  py::class_<LoopNoise>(m, "LoopNoise", "Loop information model (backend.loops.*).")
      .def(py::init<>())
      .def_readwrite("sigma_min", &LoopNoise::sigma_min, "floor of the per-axis centre noise σ (m)")
      .def_readwrite("information_scale", &LoopNoise::information_scale, "scale of the fit's information, (0, 1]");

  py::class_<LoopConsistency>(m, "LoopConsistency", "Pairwise loop consistency bounds (backend.consistency.*).")
      .def(py::init<>())
      .def_readwrite("translation_m", &LoopConsistency::translation_m, "cycle translation bound at L = 0 (m)")
      .def_readwrite("translation_per_m", &LoopConsistency::translation_per_m, "growth with path length (m/m)")
      .def_readwrite("rotation_rad", &LoopConsistency::rotation_rad, "cycle rotation bound at L = 0 (rad)")
      .def_readwrite("rotation_per_m", &LoopConsistency::rotation_per_m, "growth with path length (rad/m)");

  py::class_<SolverSettings>(m, "SolverSettings", "Ceres solver settings (backend.solver.*).")
      .def(py::init<>())
      .def_readwrite("num_threads", &SolverSettings::num_threads, "Ceres threads")
      .def_readwrite("max_iterations", &SolverSettings::max_iterations, "trust-region (Dogleg) iterations per solve")
      .def_readwrite("function_tolerance", &SolverSettings::function_tolerance, "relative cost change to stop")
      .def_readwrite("parameter_tolerance", &SolverSettings::parameter_tolerance, "relative step to stop")
      .def_readwrite("reduced_warm_start", &SolverSettings::reduced_warm_start, "start the full solve from the reduced one");

  py::class_<OnlineSettings>(m, "OnlineSettings", "Online re-optimisation (backend.online.*).")
      .def(py::init<>())
      .def_readwrite("reduced_graph", &OnlineSettings::reduced_graph, "close_loop solves the anchors' graph only")
      .def_readwrite("anchor_spacing_m", &OnlineSettings::anchor_spacing_m,
                     "path stretch (m) whose loop endpoints share one anchor (0: each its own)");

  py::class_<BackendConfig>(m, "BackendConfig", "Pose-graph back end settings (backend.*).")
      .def(py::init<>())
      .def_readwrite("odometry", &BackendConfig::odometry, "odometry information model (backend.odometry.*)")
      .def_readwrite("loops", &BackendConfig::loops, "loop information model (backend.loops.*)")
      .def_readwrite("loop_loss", &BackendConfig::loop_loss, "robust loss on loop edges")
      .def_readwrite("loss_scale", &BackendConfig::loss_scale, "a of the loss, in whitened units (σ)")
      .def_readwrite("consistency", &BackendConfig::consistency, "pairwise loop consistency (backend.consistency.*)")
      .def_readwrite("max_loop_chi2", &BackendConfig::max_loop_chi2, "reject a kept loop whose χ² exceeds this")
      .def_readwrite("max_rejection_rounds", &BackendConfig::max_rejection_rounds, "residual-check rounds")
      .def_readwrite("solver", &BackendConfig::solver, "solver settings (backend.solver.*)")
      .def_readwrite("online", &BackendConfig::online, "online re-optimisation (backend.online.*)")
      .def("validate", &BackendConfig::validate, "Raises sgtllc.Error naming the key of a value out of range.");
}

}  // namespace sgtllc::python
