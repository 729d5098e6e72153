// Ranges of the registration settings (registration_config.h), in the style of Config::validate().
#include <string>

#include "config_ranges.h"
#include "sgtllc/config.h"

namespace sgtllc {

using namespace detail;

void validateRegistrationConfig(const RegistrationConfig& r) {
  for (uint32_t id : r.ground_ids) {
    if (id > 0xFFFFu) {
      throw ConfigError("registration.ground_ids",
                        "registration.ground_ids: " + std::to_string(id) + " is not a raw id 0..65535");
    }
  }
  checkReal("registration.voxel", r.voxel, {0.05}, {10.0});
  checkInt("registration.max_points", r.max_points, 100, 1000000);
  checkReal("registration.match_voxel", r.match_voxel, {0.05}, {10.0});
  checkInt("registration.match_max_points", r.match_max_points, 100, 1000000);
  checkInt("registration.normal_neighbors", r.normal_neighbors, 5, 100);
  checkReal("registration.max_correspondence", r.max_correspondence, {0.0, false}, {10.0});
  checkReal("registration.coarse_correspondence", r.coarse_correspondence, {0.0}, {10.0});
  checkReal("registration.kernel", r.kernel, {0.0}, {10.0});
  checkInt("registration.max_iterations", r.max_iterations, 1, 500);
  checkReal("registration.convergence", r.convergence, {0.0, false}, {0.1});
  checkReal("registration.min_fitness", r.min_fitness, {0.0}, {1.0});
  checkReal("registration.max_translation_change", r.max_translation_change, {0.0, false}, {100.0});
  checkReal("registration.max_rotation_change_deg", r.max_rotation_change_deg, {0.0, false}, {180.0});
  checkReal("registration.information_sigma_min", r.information_sigma_min, {0.0, false}, {10.0});
  checkReal("registration.information_scale", r.information_scale, {0.0, false}, {1.0});
}

}  // namespace sgtllc
