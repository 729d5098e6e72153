#include <stdexcept>

#include "internal/voxel_hash.h"
#include "sgtllc/clustering.h"

namespace sgtllc {

VoxelizedCloud voxelDownsample(const std::vector<Eigen::Vector3f>& points, double leaf) {
  if (!(leaf > 0.0)) throw std::invalid_argument("voxelDownsample: leaf must be positive");
  const float inv_leaf = static_cast<float>(1.0 / leaf);
  internal::KeyIndex index(points.size() / 4 + 16);
  VoxelizedCloud out;
  for (const Eigen::Vector3f& p : points) {
    const uint32_t v = index.insert(internal::cellOf(p, inv_leaf));
    if (v == out.sums.size()) {
      out.sums.emplace_back(Eigen::Vector3d::Zero());
      out.counts.push_back(0);
    }
    out.sums[v] += p.cast<double>();
    ++out.counts[v];
  }
  out.centroids.resize(out.sums.size());
  for (size_t v = 0; v < out.sums.size(); ++v) {
    out.centroids[v] = (out.sums[v] / static_cast<double>(out.counts[v])).cast<float>();
  }
  return out;
}

}  // namespace sgtllc
