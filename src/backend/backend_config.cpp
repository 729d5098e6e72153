#include "sgtllc/config/backend_config.h"

#include <cmath>
#include <string>

#include "sgtllc/types.h"

namespace sgtllc::backend {
namespace {

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw Error("config: backend." + key + " " + what);
}

bool nonNegative(double v) { return std::isfinite(v) && v >= 0.0; }
bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

void BackendConfig::validate() const {
  require(nonNegative(odometry.translation_sigma_per_m), "odometry.translation_sigma_per_m", "must be >= 0 (m/m)");
  require(positive(odometry.translation_sigma_min), "odometry.translation_sigma_min", "must be > 0 (m)");
  require(nonNegative(odometry.rotation_sigma_per_m), "odometry.rotation_sigma_per_m", "must be >= 0 (rad/m)");
  require(nonNegative(odometry.rotation_sigma_per_rad), "odometry.rotation_sigma_per_rad", "must be >= 0 (rad/rad)");
  require(positive(odometry.rotation_sigma_min), "odometry.rotation_sigma_min", "must be > 0 (rad)");
  require(positive(loops.sigma_min), "loops.sigma_min", "must be > 0 (m)");
  require(positive(loops.information_scale) && loops.information_scale <= 1.0, "loops.information_scale",
          "must be in (0, 1]");
  require(positive(loss_scale), "loss_scale", "must be > 0");
  require(nonNegative(consistency.translation_m), "consistency.translation_m", "must be >= 0 (m)");
  require(nonNegative(consistency.translation_per_m), "consistency.translation_per_m", "must be >= 0 (m/m)");
  require(nonNegative(consistency.rotation_rad), "consistency.rotation_rad", "must be >= 0 (rad)");
  require(nonNegative(consistency.rotation_per_m), "consistency.rotation_per_m", "must be >= 0 (rad/m)");
  require(positive(max_loop_chi2), "max_loop_chi2", "must be > 0");
  require(max_rejection_rounds >= 0, "max_rejection_rounds", "must be >= 0");
  require(nonNegative(online.anchor_spacing_m), "online.anchor_spacing_m", "must be >= 0 (m)");
  require(solver.num_threads >= 1, "solver.num_threads", "must be >= 1");
  require(solver.max_iterations >= 1, "solver.max_iterations", "must be >= 1");
  require(positive(solver.function_tolerance), "solver.function_tolerance", "must be > 0");
  require(positive(solver.parameter_tolerance), "solver.parameter_tolerance", "must be > 0");
}

}  // namespace sgtllc::backend
