// Ranges of the back-end settings (backend_config.h, docs/backend.md), in the style of Config::validate(). Each
// range lies inside what backend::BackendConfig::validate() accepts, and bounds the values a real odometry or
// loop can need, so a typo (a σ in centimetres, a tolerance of 10) is caught with the key that holds it.
#include <string>

#include "config_ranges.h"
#include "sgtllc/config.h"

namespace sgtllc {

using namespace detail;

void validateBackendConfig(const backend::BackendConfig& b) {
  const backend::OdometryNoise& o = b.odometry;
  checkReal("backend.odometry.translation_sigma_per_m", o.translation_sigma_per_m, {0.0}, {1.0});
  checkReal("backend.odometry.translation_sigma_min", o.translation_sigma_min, {0.0, false}, {100.0});
  checkReal("backend.odometry.rotation_sigma_per_m", o.rotation_sigma_per_m, {0.0}, {1.0});
  checkReal("backend.odometry.rotation_sigma_per_rad", o.rotation_sigma_per_rad, {0.0}, {10.0});
  checkReal("backend.odometry.rotation_sigma_min", o.rotation_sigma_min, {0.0, false}, {10.0});
  checkReal("backend.loops.sigma_min", b.loops.sigma_min, {0.0, false}, {100.0});
  checkReal("backend.loops.information_scale", b.loops.information_scale, {0.0, false}, {1.0});
  checkReal("backend.loss_scale", b.loss_scale, {0.0, false}, {1000.0});
  const backend::LoopConsistency& c = b.consistency;
  checkReal("backend.consistency.translation_m", c.translation_m, {0.0}, {1000.0});
  checkReal("backend.consistency.translation_per_m", c.translation_per_m, {0.0}, {1.0});
  checkReal("backend.consistency.rotation_rad", c.rotation_rad, {0.0}, {10.0});  // ≥ π: no rotation bound
  checkReal("backend.consistency.rotation_per_m", c.rotation_per_m, {0.0}, {1.0});
  checkReal("backend.max_loop_chi2", b.max_loop_chi2, {0.0, false}, {1.0e12});
  checkInt("backend.max_rejection_rounds", b.max_rejection_rounds, 0, 100000);
  checkInt("backend.solver.num_threads", b.solver.num_threads, 1, kMaxThreads);
  checkInt("backend.solver.max_iterations", b.solver.max_iterations, 1, 100000);
  checkReal("backend.solver.function_tolerance", b.solver.function_tolerance, {0.0, false}, {1.0});
  checkReal("backend.solver.parameter_tolerance", b.solver.parameter_tolerance, {0.0, false}, {1.0});
  checkReal("backend.online.anchor_spacing_m", b.online.anchor_spacing_m, {0.0}, {1000.0});
}

}  // namespace sgtllc
