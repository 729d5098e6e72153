// The settings of the pose-graph back end (config/backend_config.h documents each group; docs/backend.md the
// model). Each range bounds what a real odometry or loop can need, so that a typo (a σ in centimetres, a
// tolerance of 10) is caught with the key that holds it.
#include "setting_table.h"

namespace sgtllc::detail {

void addBackendSettings(std::vector<Setting>* out) {
  using namespace backend;
  SectionTable<OdometryNoise> o("backend.odometry", [](Config& c) -> OdometryNoise& { return c.backend.odometry; }, out);
  o.number("translation_sigma_per_m", &OdometryNoise::translation_sigma_per_m, "[0, 1]", "m/m",
           "odometry translation σ per metre travelled");
  o.number("translation_sigma_min", &OdometryNoise::translation_sigma_min, "(0, 100]", "m", "odometry translation σ floor");
  o.number("rotation_sigma_per_m", &OdometryNoise::rotation_sigma_per_m, "[0, 1]", "rad/m",
           "odometry rotation σ per metre travelled");
  o.number("rotation_sigma_per_rad", &OdometryNoise::rotation_sigma_per_rad, "[0, 10]", "rad/rad",
           "odometry rotation σ per radian turned");
  o.number("rotation_sigma_min", &OdometryNoise::rotation_sigma_min, "(0, 10]", "rad", "odometry rotation σ floor");

  SectionTable<LoopNoise> l("backend.loops", [](Config& c) -> LoopNoise& { return c.backend.loops; }, out);
  l.number("sigma_min", &LoopNoise::sigma_min, "(0, 100]", "m", "floor of a loop's per-axis node-centre noise σ");
  l.number("information_scale", &LoopNoise::information_scale, "(0, 1]", "",
           "loop information × this, for errors shared by a frame's centres");

  SectionTable<BackendConfig> b("backend", [](Config& c) -> BackendConfig& { return c.backend; }, out);
  b.choice("loop_loss", &BackendConfig::loop_loss,
           {{"none", RobustLoss::kNone}, {"huber", RobustLoss::kHuber}, {"cauchy", RobustLoss::kCauchy}},
           "robust loss on loop edges");
  b.number("loss_scale", &BackendConfig::loss_scale, "(0, 1000]", "σ", "scale a of the robust loss, in whitened units");

  using LC = LoopConsistency;
  SectionTable<LC> c("backend.consistency", [](Config& config) -> LC& { return config.backend.consistency; }, out);
  c.number("translation_m", &LC::translation_m, "[0, 1000]", "m", "loop pair cycle translation bound at zero path length");
  c.number("translation_per_m", &LC::translation_per_m, "[0, 1]", "m/m", "... growth per metre of odometry path");
  // π or more: no rotation bound.
  c.number("rotation_rad", &LC::rotation_rad, "[0, 10]", "rad", "loop pair cycle rotation bound at zero path length");
  c.number("rotation_per_m", &LC::rotation_per_m, "[0, 1]", "rad/m", "... growth per metre of odometry path");

  b.number("max_loop_chi2", &BackendConfig::max_loop_chi2, "(0, 1e12]", "",
           "reject a kept loop whose χ² after optimising exceeds this");
  b.number("max_rejection_rounds", &BackendConfig::max_rejection_rounds, "[0, 100000]", "",
           "residual-check rounds (each re-optimises)");

  SectionTable<SolverSettings> s("backend.solver", [](Config& config) -> SolverSettings& { return config.backend.solver; },
                                 out);
  s.number("num_threads", &SolverSettings::num_threads, "[1, " + std::to_string(kMaxThreads) + "]", "",
           "Ceres threads; results do not depend on it (--threads sets it too)");
  s.number("max_iterations", &SolverSettings::max_iterations, "[1, 100000]", "", "trust-region (Dogleg) iterations per solve");
  s.number("function_tolerance", &SolverSettings::function_tolerance, "(0, 1]", "",
           "stop when the relative cost change is below this");
  s.number("parameter_tolerance", &SolverSettings::parameter_tolerance, "(0, 1]", "",
           "stop when the relative step is below this");
  s.flag("reduced_warm_start", &SolverSettings::reduced_warm_start, "start the full solve from the reduced graph's solution");

  SectionTable<OnlineSettings> n("backend.online", [](Config& config) -> OnlineSettings& { return config.backend.online; },
                                 out);
  n.flag("reduced_graph", &OnlineSettings::reduced_graph,
         "online re-optimisation over loop-endpoint anchors only (false: the full graph every loop)");
  n.number("anchor_spacing_m", &OnlineSettings::anchor_spacing_m, "[0, 1000]", "m",
           "path stretch whose loop endpoints share one online anchor; 0: each its own");

  SectionTable<SessionSettings> e("backend.sessions",
                                  [](Config& config) -> SessionSettings& { return config.backend.sessions; }, out);
  e.number("min_inter_loops", &SessionSettings::min_inter_loops, "[1, 1000]", "",
           "agreeing inter-session loops a session needs to join a map (run --map)");
  e.number("keep_distance_m", &SessionSettings::keep_distance_m, "[0, 1000]", "m",
           "a recognised session frame with a map frame this near (and keep_heading_deg) is not added; 0: all are");
  e.number("keep_heading_deg", &SessionSettings::keep_heading_deg, "[0, 180]", "deg",
           "... whose forward axis is within this of its own");
  e.number("max_covering_sessions", &SessionSettings::max_covering_sessions, "[1, 1000]", "",
           "an unrecognised frame the map covers is added only while its covering map frames come from fewer sessions");
}

}  // namespace sgtllc::detail
