#include "sgtllc/registration/cloud_store.h"

#include <utility>

namespace sgtllc {

CloudStore::CloudStore(const RegistrationConfig& config, const LabelConfig& labels)
    : config_(config), labels_(labels) {}

RegistrationClouds CloudStore::prepare(const LabeledCloud& cloud) const {
  if (!enabled()) return {};
  RegistrationClouds out;
  out.stable = stableRegistrationPoints(cloud, labels_, config_.ground_ids);
  out.match = compactCloud(reduceRegistrationPoints(out.stable, config_.match_voxel, config_.match_max_points));
  return out;
}

std::vector<Eigen::Vector3f> CloudStore::queryCloud(const std::vector<Eigen::Vector3f>& stable) const {
  return compactCloud(reduceRegistrationPoints(stable, config_.voxel, config_.max_points)).expand();
}

void CloudStore::add(CompactCloud cloud) {
  if (!enabled()) return;
  bytes_ += cloud.bytes();
  clouds_.push_back(std::move(cloud));
}

std::optional<Refinement> CloudStore::refine(const std::vector<Eigen::Vector3f>& query_points, int match,
                                             const Eigen::Matrix4d& T_seed) const {
  if (!enabled() || match < 0 || match >= size()) return std::nullopt;
  return refinePose(query_points, clouds_[static_cast<size_t>(match)].expand(), T_seed, config_);
}

}  // namespace sgtllc
