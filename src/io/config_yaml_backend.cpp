#include "config_yaml_backend.h"

namespace sgtllc::io::detail {

void addBackendFields(const BackendFieldMakers& add) {
  using B = backend::BackendConfig;
  auto number = [&add](const char* key, const char* comment, double& (*ref)(B&)) {
    add.number(std::string("backend.") + key, comment, [ref](Config& c) -> double& { return ref(c.backend); });
  };
  auto integer = [&add](const char* key, const char* comment, int& (*ref)(B&)) {
    add.integer(std::string("backend.") + key, comment, [ref](Config& c) -> int& { return ref(c.backend); });
  };
  number("odometry.translation_sigma_per_m", "odometry translation σ per metre travelled (m/m)",
         [](B& b) -> double& { return b.odometry.translation_sigma_per_m; });
  number("odometry.translation_sigma_min", "odometry translation σ floor (m)",
         [](B& b) -> double& { return b.odometry.translation_sigma_min; });
  number("odometry.rotation_sigma_per_m", "odometry rotation σ per metre travelled (rad/m)",
         [](B& b) -> double& { return b.odometry.rotation_sigma_per_m; });
  number("odometry.rotation_sigma_per_rad", "odometry rotation σ per radian turned (rad/rad)",
         [](B& b) -> double& { return b.odometry.rotation_sigma_per_rad; });
  number("odometry.rotation_sigma_min", "odometry rotation σ floor (rad)",
         [](B& b) -> double& { return b.odometry.rotation_sigma_min; });
  number("loops.sigma_min", "floor of a loop's per-axis node-centre noise σ (m)",
         [](B& b) -> double& { return b.loops.sigma_min; });
  number("loops.information_scale", "loop information × this, for errors shared by a frame's centres",
         [](B& b) -> double& { return b.loops.information_scale; });
  add.loss("backend.loop_loss", "robust loss on loop edges",
           [](Config& c) -> backend::RobustLoss& { return c.backend.loop_loss; },
           {{"none", backend::RobustLoss::kNone},
            {"huber", backend::RobustLoss::kHuber},
            {"cauchy", backend::RobustLoss::kCauchy}});
  number("loss_scale", "scale a of the robust loss (whitened units, σ)", [](B& b) -> double& { return b.loss_scale; });
  number("consistency.translation_m", "loop pair cycle translation bound at zero path length (m)",
         [](B& b) -> double& { return b.consistency.translation_m; });
  number("consistency.translation_per_m", "... growth per metre of odometry path (m/m)",
         [](B& b) -> double& { return b.consistency.translation_per_m; });
  number("consistency.rotation_rad", "loop pair cycle rotation bound at zero path length (rad)",
         [](B& b) -> double& { return b.consistency.rotation_rad; });
  number("consistency.rotation_per_m", "... growth per metre of odometry path (rad/m)",
         [](B& b) -> double& { return b.consistency.rotation_per_m; });
  number("max_loop_chi2", "reject a kept loop whose χ² after optimising exceeds this",
         [](B& b) -> double& { return b.max_loop_chi2; });
  integer("max_rejection_rounds", "residual-check rounds (each re-optimises)",
          [](B& b) -> int& { return b.max_rejection_rounds; });
  integer("solver.num_threads", "Ceres threads; results do not depend on it (--threads sets it too)",
          [](B& b) -> int& { return b.solver.num_threads; });
  integer("solver.max_iterations", "trust-region (Dogleg) iterations per solve",
          [](B& b) -> int& { return b.solver.max_iterations; });
  number("solver.function_tolerance", "stop when the relative cost change is below this",
         [](B& b) -> double& { return b.solver.function_tolerance; });
  number("solver.parameter_tolerance", "stop when the relative step is below this",
         [](B& b) -> double& { return b.solver.parameter_tolerance; });
  add.boolean("backend.solver.reduced_warm_start", "start the full solve from the reduced graph's solution",
              [](Config& c) -> bool& { return c.backend.solver.reduced_warm_start; });
  add.boolean("backend.online.reduced_graph",
              "online re-optimisation over loop-endpoint anchors only (false: the full graph every loop)",
              [](Config& c) -> bool& { return c.backend.online.reduced_graph; });
  number("online.anchor_spacing_m", "path stretch whose loop endpoints share one online anchor (m; 0: each its own)",
         [](B& b) -> double& { return b.online.anchor_spacing_m; });
}

}  // namespace sgtllc::io::detail
