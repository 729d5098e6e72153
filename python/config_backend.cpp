// BackendConfig and its sections (include/sgtllc/config/backend_config.h, docs/backend.md). Their settings are
// properties made from the settings table (settings.h); here are the enum and the structure.
#include "bindings.h"
#include "opaque.h"
#include "settings.h"
#include "sgtllc/config/backend_config.h"

namespace sgtllc::python {

void bindBackendConfig(py::module_& m) {
  using namespace sgtllc::backend;
  choiceEnum<RobustLoss>(m, "RobustLoss", "Robust loss on loop edges (backend.loop_loss).")
      .value("NONE", RobustLoss::kNone, "plain least squares")
      .value("HUBER", RobustLoss::kHuber, "quadratic below loss_scale, linear above")
      .value("CAUCHY", RobustLoss::kCauchy, "a² log(1 + s²/a²) (default)");

  settingsClass<OdometryNoise>(m, "OdometryNoise", "Odometry information model (backend.odometry.*).")
      .def(py::init<>());
  settingsClass<LoopNoise>(m, "LoopNoise", "Loop information model (backend.loops.*).").def(py::init<>());
  settingsClass<LoopConsistency>(m, "LoopConsistency", "Pairwise loop consistency bounds (backend.consistency.*).")
      .def(py::init<>());
  settingsClass<SolverSettings>(m, "SolverSettings", "Ceres solver settings (backend.solver.*).").def(py::init<>());
  settingsClass<OnlineSettings>(m, "OnlineSettings", "Online re-optimisation (backend.online.*).").def(py::init<>());
  settingsClass<SessionSettings>(m, "SessionSettings", "A new session joining a map (backend.sessions.*).")
      .def(py::init<>());

  settingsClass<BackendConfig>(m, "BackendConfig", "Pose-graph back end settings (backend.*).")
      .def(py::init<>())
      .def_readwrite("odometry", &BackendConfig::odometry, "odometry information model (backend.odometry.*)")
      .def_readwrite("loops", &BackendConfig::loops, "loop information model (backend.loops.*)")
      .def_readwrite("consistency", &BackendConfig::consistency, "pairwise loop consistency (backend.consistency.*)")
      .def_readwrite("solver", &BackendConfig::solver, "solver settings (backend.solver.*)")
      .def_readwrite("online", &BackendConfig::online, "online re-optimisation (backend.online.*)")
      .def_readwrite("sessions", &BackendConfig::sessions, "a new session joining a map (backend.sessions.*)")
      .def("validate", &BackendConfig::validate,
           "Raises ConfigError naming the key of a value out of range, as Config.validate() does.");
}

}  // namespace sgtllc::python
