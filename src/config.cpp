#include "sgtllc/config.h"

#include <cmath>
#include <string>

namespace sgtllc {
namespace {

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw Error("config: " + key + " " + what);
}

bool finite(double v) { return std::isfinite(v); }

}  // namespace

void Config::validate() const {
  for (const auto& [id, cls] : labels.custom_map) {
    require(cls >= -1 && cls < kNumClasses, "labels.custom_map[" + std::to_string(id) + "]",
            "must be a class index 0..6 or -1 (dropped), got " + std::to_string(cls));
  }
  for (int c = 0; c < kNumClasses; ++c) {
    const std::string key = std::string("cluster.") + kClassNames[c];
    const ClassClusterConfig& p = cluster.classes[c];
    // Lower bounds keep voxel cells of points within ±1e6 m inside the exact integer cell range.
    require(finite(p.voxel) && (p.voxel == 0.0 || p.voxel >= 0.001), key + ".voxel",
            "must be 0 (no downsampling) or >= 0.001 m");
    require(finite(p.radius) && p.radius >= 0.001, key + ".radius", "must be >= 0.001 m");
    require(p.min_size >= 1, key + ".min_size", "must be >= 1");
  }
  require(cluster.max_neighbors >= 1, "cluster.max_neighbors", "must be >= 1");
  require(finite(cluster.duplicate_radius) && cluster.duplicate_radius >= 0.0, "cluster.duplicate_radius",
          "must be >= 0");
  require(finite(graph.sigma_d) && graph.sigma_d > 0.0, "graph.sigma_d", "must be > 0");
  require(retrieval.num_candidates >= 1, "retrieval.num_candidates", "must be >= 1");
  require(retrieval.exclude_recent >= 1, "retrieval.exclude_recent", "must be >= 1 (a frame never matches itself)");
  require(retrieval.warmup_frames >= 0, "retrieval.warmup_frames", "must be >= 0");
  require(finite(association.sigma_1) && association.sigma_1 >= -1.0 && association.sigma_1 <= 1.0,
          "association.sigma_1", "must be a cosine in [-1, 1]");
  require(finite(association.max_delta_aj) && association.max_delta_aj > 0.0, "association.max_delta_aj",
          "must be > 0");
  require(finite(association.sigma_2) && association.sigma_2 >= 0.0, "association.sigma_2", "must be >= 0");
  require(association.entries >= 1 && association.entries <= 7, "association.entries",
          "must keep at least one of the v_i, v_j, v_k entries");
  const VerificationConfig& v = verification;
  require(finite(v.sigma_3) && v.sigma_3 >= 0.0, "verification.sigma_3", "must be >= 0");
  require(v.min_associations >= 1, "verification.min_associations", "must be >= 1");
  require(v.ransac_iterations >= 1, "verification.ransac_iterations", "must be >= 1");
  require(v.ransac_sample_size >= 3, "verification.ransac_sample_size", "must be >= 3 (a rigid fit needs 3 points)");
  require(finite(v.inlier_threshold) && v.inlier_threshold > 0.0, "verification.inlier_threshold", "must be > 0");
  require(v.min_inliers >= 1, "verification.min_inliers", "must be >= 1");
  require(finite(v.min_inlier_fraction) && v.min_inlier_fraction >= 0.0 && v.min_inlier_fraction <= 1.0,
          "verification.min_inlier_fraction", "must be in [0, 1]");
  require(finite(v.ransac_confidence) && v.ransac_confidence > 0.0 && v.ransac_confidence <= 1.0,
          "verification.ransac_confidence", "must be in (0, 1]");
  require(finite(v.sigma_4), "verification.sigma_4", "must be a finite number");
  require(threads >= 1 && threads <= kMaxThreads, "threads", "must be in 1.." + std::to_string(kMaxThreads));
}

}  // namespace sgtllc
