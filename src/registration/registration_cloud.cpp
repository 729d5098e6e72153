#include "sgtllc/registration/registration_cloud.h"

#include <cmath>
#include <string>

#include "sgtllc/clustering.h"
#include "sgtllc/node_extraction.h"

namespace sgtllc {

namespace {

void checkSizes(const LabeledCloud& cloud) {
  if (cloud.points.size() != cloud.labels.size()) {
    throw Error("registration: " + std::to_string(cloud.points.size()) + " points but " +
                std::to_string(cloud.labels.size()) + " labels");
  }
}

/// One lookup per point: the class table of the labels plus the ground ids (low 16 bits, as LabelMap).
std::vector<uint8_t> stableIds(const LabelMap& labels, const std::vector<uint32_t>& ground_ids) {
  std::vector<uint8_t> use(1u << 16, 0);
  for (uint32_t id = 0; id < use.size(); ++id) use[id] = labels.classOf(id) >= 0;
  for (uint32_t id : ground_ids) use[id & 0xFFFFu] = 1;
  return use;
}

bool isStable(const Eigen::Vector3f& p, uint32_t id, const std::vector<uint8_t>& use) {
  return use[id & 0xFFFFu] && p.allFinite() && p.cwiseAbs().maxCoeff() <= kMaxCoordinate;
}

}  // namespace

std::vector<Eigen::Vector3f> stableRegistrationPoints(const LabeledCloud& cloud, const LabelMap& labels,
                                                      const std::vector<uint32_t>& ground_ids) {
  checkSizes(cloud);
  const std::vector<uint8_t> use = stableIds(labels, ground_ids);
  std::vector<Eigen::Vector3f> stable;
  stable.reserve(cloud.points.size());
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    if (isStable(cloud.points[i], cloud.labels[i], use)) stable.push_back(cloud.points[i]);
  }
  return stable;
}

std::vector<Eigen::Vector3f> reduceRegistrationPoints(const std::vector<Eigen::Vector3f>& stable, double voxel,
                                                      int max_points) {
  std::vector<Eigen::Vector3f> voxels = voxelDownsample(stable, voxel).centroids;
  const size_t cap = static_cast<size_t>(max_points);
  if (voxels.size() <= cap) return voxels;
  // An even stride over voxels in scan order keeps the cover of the whole scan, not its first sectors.
  std::vector<Eigen::Vector3f> kept;
  kept.reserve(cap);
  for (size_t k = 0; k < cap; ++k) kept.push_back(voxels[k * voxels.size() / cap]);
  return kept;
}

std::vector<Eigen::Vector3f> registrationPoints(const LabeledCloud& cloud, const LabelMap& labels,
                                                const std::vector<uint32_t>& ground_ids, double voxel,
                                                int max_points) {
  return reduceRegistrationPoints(stableRegistrationPoints(cloud, labels, ground_ids), voxel, max_points);
}

std::vector<Eigen::Vector3f> registrationPoints(LabeledCloud&& cloud, const LabelMap& labels,
                                                const std::vector<uint32_t>& ground_ids, double voxel,
                                                int max_points) {
  checkSizes(cloud);
  const std::vector<uint8_t> use = stableIds(labels, ground_ids);
  // The stable points in place, in scan order, and the labels freed: no second copy of a big scan
  // (BENCHMARKS.md "Memory on big inputs").
  std::vector<Eigen::Vector3f>& points = cloud.points;
  size_t kept = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (isStable(points[i], cloud.labels[i], use)) points[kept++] = points[i];
  }
  points.resize(kept);
  std::vector<uint32_t>().swap(cloud.labels);
  const LabeledCloud consumed = std::move(cloud);  // the caller's cloud is left empty, its memory freed on return
  return reduceRegistrationPoints(consumed.points, voxel, max_points);
}

std::vector<Eigen::Vector3f> CompactCloud::expand() const {
  std::vector<Eigen::Vector3f> out;
  out.reserve(points.size());
  for (const auto& q : points) out.emplace_back(q[0] * kStep, q[1] * kStep, q[2] * kStep);
  return out;
}

CompactCloud compactCloud(const std::vector<Eigen::Vector3f>& points) {
  CompactCloud out;
  out.points.reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    const Eigen::Vector3f cells = (p / CompactCloud::kStep).array().round();
    if (cells.cwiseAbs().maxCoeff() > 32767.0f) continue;
    out.points.push_back({static_cast<int16_t>(cells.x()), static_cast<int16_t>(cells.y()),
                          static_cast<int16_t>(cells.z())});
  }
  return out;
}

}  // namespace sgtllc
