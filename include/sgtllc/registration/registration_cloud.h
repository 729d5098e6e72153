/// @file registration_cloud.h
/// @brief The points fine registration works on: a scan's stable-class points, voxel-downsampled and capped, and
///        their compact form kept per frame by the online detector (docs/registration.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/labels.h"
#include "sgtllc/config/registration_config.h"
#include <utility>

#include "sgtllc/types.h"

namespace sgtllc {

/// The points of @p cloud registration can use, in scan order: a stable class (LabelMap::classOf ≥ 0) or one of
/// @p ground_ids (RegistrationConfig::ground_ids), finite, within ±kMaxCoordinate. Throws sgtllc::Error if points
/// and labels differ in length.
std::vector<Eigen::Vector3f> stableRegistrationPoints(const LabeledCloud& cloud, const LabelMap& labels,
                                                      const std::vector<uint32_t>& ground_ids);
/// @p stable (stableRegistrationPoints) reduced to one centroid per voxel of edge @p voxel (m) in order of first
/// appearance, then at most @p max_points of them by an even stride over the voxels.
std::vector<Eigen::Vector3f> reduceRegistrationPoints(const std::vector<Eigen::Vector3f>& stable, double voxel,
                                                      int max_points);

/// The points of @p cloud registration uses: a stable class (LabelMap::classOf ≥ 0) or one of @p ground_ids
/// (RegistrationConfig::ground_ids), finite, within ±kMaxCoordinate; one centroid per voxel of edge @p voxel (m) in
/// order of first appearance, then at most @p max_points of them by an even stride. Throws sgtllc::Error if points
/// and labels differ in length.
std::vector<Eigen::Vector3f> registrationPoints(const LabeledCloud& cloud, const LabelMap& labels,
                                                const std::vector<uint32_t>& ground_ids, double voxel,
                                                int max_points);
/// The same points from a cloud the caller gives up: filtered in place and its labels freed, so a big scan is not
/// copied (BENCHMARKS.md "Memory on big inputs"); @p cloud is left empty.
std::vector<Eigen::Vector3f> registrationPoints(LabeledCloud&& cloud, const LabelMap& labels,
                                                const std::vector<uint32_t>& ground_ids, double voxel,
                                                int max_points);

/// The query (source) cloud of a refinement: RegistrationConfig::ground_ids, voxel and max_points.
inline std::vector<Eigen::Vector3f> queryPoints(const LabeledCloud& cloud, const LabelMap& labels,
                                                const RegistrationConfig& config) {
  return registrationPoints(cloud, labels, config.ground_ids, config.voxel, config.max_points);
}
inline std::vector<Eigen::Vector3f> queryPoints(LabeledCloud&& cloud, const LabelMap& labels,
                                                const RegistrationConfig& config) {
  return registrationPoints(std::move(cloud), labels, config.ground_ids, config.voxel, config.max_points);
}
/// The match (target) cloud: the finer RegistrationConfig::match_voxel and match_max_points; the one stored online.
inline std::vector<Eigen::Vector3f> matchPoints(const LabeledCloud& cloud, const LabelMap& labels,
                                                const RegistrationConfig& config) {
  return registrationPoints(cloud, labels, config.ground_ids, config.match_voxel, config.match_max_points);
}
inline std::vector<Eigen::Vector3f> matchPoints(LabeledCloud&& cloud, const LabelMap& labels,
                                                const RegistrationConfig& config) {
  return registrationPoints(std::move(cloud), labels, config.ground_ids, config.match_voxel,
                            config.match_max_points);
}

/// A registration cloud quantised to whole centimetres in int16: 6 bytes per point, ±327.67 m.
struct CompactCloud {
  static constexpr float kStep = 0.01f;  ///< quantisation step (m); the rounding error is at most 5 mm per axis
  std::vector<std::array<int16_t, 3>> points;

  /// Bytes of point data (6 per point).
  size_t bytes() const { return points.size() * sizeof(points[0]); }
  /// The points in metres.
  std::vector<Eigen::Vector3f> expand() const;
};

/// Quantises @p points; points beyond ±327.67 m on an axis (beyond any LiDAR's range) are left out.
CompactCloud compactCloud(const std::vector<Eigen::Vector3f>& points);

}  // namespace sgtllc
