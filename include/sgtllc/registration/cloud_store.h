/// @file cloud_store.h
/// @brief The online detector's per-frame store of compact registration clouds, and the refinement of a declared
///        loop from it (RegistrationConfig::online; docs/registration.md).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/labels.h"
#include "sgtllc/registration/icp.h"
#include "sgtllc/registration/registration_cloud.h"

namespace sgtllc {

/// A frame's clouds for the online refinement: the one stored (match role), and the points the moved one (query
/// role) is made from if the frame closes a loop: most frames do not, and the query cloud's fine voxels were the
/// largest part of a frame's registration cost (BENCHMARKS.md, "Fine registration"). Both empty when the store is
/// disabled or the frame came as nodes.
struct RegistrationClouds {
  CompactCloud match;                  ///< matchPoints, quantised: what the store keeps
  std::vector<Eigen::Vector3f> stable;  ///< stableRegistrationPoints of the scan, for CloudStore::queryCloud
};

/// One CompactCloud per frame, in frame order: at most 6 · RegistrationConfig::max_points bytes each. Empty (and
/// nothing stored) unless RegistrationConfig::online.
class CloudStore {
 public:
  CloudStore(const RegistrationConfig& config, const LabelConfig& labels);

  bool enabled() const { return config_.online; }
  /// The stored cloud and the stable points of @p cloud; empty when the store is disabled. A pure function of the
  /// scan (safe in parallel).
  RegistrationClouds prepare(const LabeledCloud& cloud) const;
  /// The query cloud (queryPoints, quantised like the stored ones) of a frame's RegistrationClouds::stable.
  std::vector<Eigen::Vector3f> queryCloud(const std::vector<Eigen::Vector3f>& stable) const;
  /// Appends the next frame's cloud (empty for a frame given as nodes: its loops keep the SVD pose).
  void add(CompactCloud cloud);
  /// Refines @p T_seed of @p query_points (queryCloud) against stored frame @p match; nullopt if the store is
  /// disabled or the frame unknown. A frame is stored after its loop is decided, so the query is passed in.
  std::optional<Refinement> refine(const std::vector<Eigen::Vector3f>& query_points, int match,
                                   const Eigen::Matrix4d& T_seed) const;

  int size() const { return static_cast<int>(clouds_.size()); }
  /// Bytes of point data of all stored frames.
  size_t bytes() const { return bytes_; }

 private:
  RegistrationConfig config_;
  LabelMap labels_;
  std::vector<CompactCloud> clouds_;
  size_t bytes_ = 0;
};

}  // namespace sgtllc
