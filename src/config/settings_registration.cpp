// The settings of fine registration (config/registration_config.h documents each field; docs/registration.md the
// method).
#include "setting_table.h"

namespace sgtllc::detail {

void addRegistrationSettings(std::vector<Setting>* out) {
  using R = RegistrationConfig;
  SectionTable<R> r("registration", [](Config& c) -> R& { return c.registration; }, out);
  r.flag("pair", &R::pair, "refine the pose of `sgtllc pair` by point-to-plane ICP");
  r.flag("online", &R::online, "refine each declared loop online (keeps <= 6 * match_max_points bytes per frame)");
  r.ids("ground_ids", &R::ground_ids, "raw ids whose points also join the ICP clouds (not the graph): the ground");
  r.number("voxel", &R::voxel, "[0.05, 10]", "m", "voxel leaf of the query points before ICP");
  r.number("max_points", &R::max_points, "[100, 1000000]", "", "most query points after downsampling");
  r.number("match_voxel", &R::match_voxel, "[0.05, 10]", "m", "voxel leaf of the match scan's stable-class points");
  r.number("match_max_points", &R::match_max_points, "[100, 1000000]", "", "most match points (online: 6 bytes each per frame)");
  r.number("normal_neighbors", &R::normal_neighbors, "[5, 100]", "", "neighbours of a target point's normal");
  r.number("max_correspondence", &R::max_correspondence, "(0, 10]", "m", "pair a point only with a target point this close");
  r.number("coarse_correspondence", &R::coarse_correspondence, "[0, 10]", "m",
           "pairing distance of a first, coarse ICP stage; 0 = none");
  r.number("kernel", &R::kernel, "[0, 10]", "m", "scale of the Cauchy weight on point-to-plane residuals; 0 = none");
  r.number("max_iterations", &R::max_iterations, "[1, 500]", "", "Gauss-Newton iterations at most");
  r.number("convergence", &R::convergence, "(0, 0.1]", "m and rad", "converged once an update is below this");
  r.number("min_fitness", &R::min_fitness, "[0, 1]", "", "keep the SVD pose if fewer query points than this share are paired");
  r.number("max_translation_change", &R::max_translation_change, "(0, 100]", "m",
           "keep the SVD pose if ICP moves it further than this");
  r.number("max_rotation_change_deg", &R::max_rotation_change_deg, "(0, 180]", "deg", "... or turns it by more than this");
  r.number("information_sigma_min", &R::information_sigma_min, "(0, 10]", "m",
           "floor of the residual sigma in the loop information");
  r.number("information_scale", &R::information_scale, "(0, 1]", "", "ICP information x this (points are not independent)");
}

}  // namespace sgtllc::detail
