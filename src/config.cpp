#include "sgtllc/config.h"

#include <string>

#include "config_ranges.h"

namespace sgtllc {

using namespace detail;

void Config::validate() const {
  // Ranges are documented field by field in config.h; keep the two in step.
  for (const auto& [id, cls] : labels.custom_map) {
    checkInt("labels.custom_map[" + std::to_string(id) + "]", cls, -1, kNumClasses - 1);
  }
  for (int c = 0; c < kNumClasses; ++c) {
    const std::string key = std::string("cluster.") + kClassNames[c];
    const ClassClusterConfig& p = cluster.classes[c];
    // Lower bounds keep voxel cells of points within ±1e6 m inside the exact integer cell range.
    if (p.voxel != 0.0 && !inside(p.voxel, {0.001}, {10.0})) {
      outOfRange(key + ".voxel", text(p.voxel), "0 (no downsampling) or [0.001, 10]");
    }
    checkReal(key + ".radius", p.radius, {0.001}, {10.0});
    checkInt(key + ".min_size", p.min_size, 1, 1000000);
  }
  checkInt("cluster.max_neighbors", cluster.max_neighbors, 1, 10000);
  checkReal("cluster.duplicate_radius", cluster.duplicate_radius, {0.0}, {100.0});
  checkReal("graph.sigma_d", graph.sigma_d, {0.0, false}, {1000.0});
  checkInt("graph.max_nodes", graph.max_nodes, 1, kMaxGraphNodes);
  checkInt("retrieval.num_candidates", retrieval.num_candidates, 1, 1000);
  checkInt("retrieval.exclude_recent", retrieval.exclude_recent, 1, kMaxFrames);  // a frame never matches itself
  checkInt("retrieval.warmup_frames", retrieval.warmup_frames, 0, kMaxFrames);
  checkReal("association.sigma_1", association.sigma_1, {-1.0}, {1.0});
  checkReal("association.max_delta_aj", association.max_delta_aj, {0.0, false}, {1.0e6});
  // S is a share of slots with score ratio and a count of them (at most kNumSlots = 49) with score count.
  const bool count = association.score == NodeScore::kCount;
  if (!inside(association.sigma_2, {0.0}, {count ? 49.0 : 1.0})) {
    outOfRange("association.sigma_2", text(association.sigma_2),
               count ? "[0, 49] (association.score: count)" : "[0, 1] (association.score: ratio; [0, 49] with count)");
  }
  if (association.entries < 1 || association.entries > 7) {
    throw ConfigError("association.entries", "association.entries must keep at least one of the v_i, v_j, v_k entries");
  }
  const VerificationConfig& v = verification;
  checkReal("verification.sigma_3", v.sigma_3, {0.0}, {1.0});
  checkInt("verification.min_associations", v.min_associations, 1, kMaxGraphNodes);
  checkInt("verification.ransac_iterations", v.ransac_iterations, 1, 10000);
  checkInt("verification.ransac_sample_size", v.ransac_sample_size, 3, 100);  // a rigid fit needs 3 points
  checkReal("verification.inlier_threshold", v.inlier_threshold, {0.0, false}, {10.0});
  checkInt("verification.min_inliers", v.min_inliers, 1, kMaxGraphNodes);
  checkReal("verification.min_inlier_fraction", v.min_inlier_fraction, {0.0}, {1.0});
  checkReal("verification.ransac_confidence", v.ransac_confidence, {0.0, false}, {1.0});
  checkReal("verification.sigma_4", v.sigma_4, {0.0}, {1.0});
  checkInt("threads", threads, 1, kMaxThreads);
  validateBackendConfig(backend);
}

}  // namespace sgtllc
