// The `registration.*` keys of the configuration YAML (config_fields.cpp); the fields are documented in
// include/sgtllc/config/registration_config.h.
#include "config_yaml_backend.h"

namespace sgtllc::io::detail {

void addRegistrationFields(const BackendFieldMakers& add) {
  using R = RegistrationConfig;
  auto number = [&add](const char* key, const char* comment, double& (*ref)(R&)) {
    add.number(std::string("registration.") + key, comment, [ref](Config& c) -> double& { return ref(c.registration); });
  };
  auto integer = [&add](const char* key, const char* comment, int& (*ref)(R&)) {
    add.integer(std::string("registration.") + key, comment, [ref](Config& c) -> int& { return ref(c.registration); });
  };
  auto boolean = [&add](const char* key, const char* comment, bool& (*ref)(R&)) {
    add.boolean(std::string("registration.") + key, comment, [ref](Config& c) -> bool& { return ref(c.registration); });
  };
  boolean("pair", "refine the pose of `sgtllc pair` by point-to-plane ICP", [](R& r) -> bool& { return r.pair; });
  boolean("online", "refine each declared loop online (keeps <= 6 * match_max_points bytes per frame)",
          [](R& r) -> bool& { return r.online; });
  add.ids("registration.ground_ids", "raw ids whose points also join the ICP clouds (not the graph): the ground",
          [](Config& c) -> std::vector<uint32_t>& { return c.registration.ground_ids; });
  number("voxel", "voxel leaf of the query points before ICP (m)", [](R& r) -> double& { return r.voxel; });
  integer("max_points", "most query points after downsampling", [](R& r) -> int& { return r.max_points; });
  number("match_voxel", "voxel leaf of the match scan's stable-class points (m)",
         [](R& r) -> double& { return r.match_voxel; });
  integer("match_max_points", "most match points (online: 6 bytes each per frame)",
          [](R& r) -> int& { return r.match_max_points; });
  integer("normal_neighbors", "neighbours of a target point's normal", [](R& r) -> int& { return r.normal_neighbors; });
  number("max_correspondence", "pair a point only with a target point this close (m)",
         [](R& r) -> double& { return r.max_correspondence; });
  number("coarse_correspondence", "pairing distance of a first, coarse ICP stage (m); 0 = none",
         [](R& r) -> double& { return r.coarse_correspondence; });
  number("kernel", "scale of the Cauchy weight on point-to-plane residuals (m); 0 = none",
         [](R& r) -> double& { return r.kernel; });
  integer("max_iterations", "Gauss-Newton iterations at most", [](R& r) -> int& { return r.max_iterations; });
  number("convergence", "converged once an update is below this (m and rad)",
         [](R& r) -> double& { return r.convergence; });
  number("min_fitness", "keep the SVD pose if fewer query points than this share are paired",
         [](R& r) -> double& { return r.min_fitness; });
  number("max_translation_change", "keep the SVD pose if ICP moves it further than this (m)",
         [](R& r) -> double& { return r.max_translation_change; });
  number("max_rotation_change_deg", "... or turns it by more than this (degrees)",
         [](R& r) -> double& { return r.max_rotation_change_deg; });
  number("information_sigma_min", "floor of the residual sigma in the loop information (m)",
         [](R& r) -> double& { return r.information_sigma_min; });
  number("information_scale", "ICP information x this (points are not independent)",
         [](R& r) -> double& { return r.information_scale; });
}

}  // namespace sgtllc::io::detail
