#include <stdexcept>
#include <utility>

#include "internal/voxel_hash.h"
#include "sgtllc/clustering.h"

namespace sgtllc {

VoxelizedCloud voxelDownsample(const std::vector<Eigen::Vector3f>& points, double leaf) {
  if (!(leaf > 0.0)) throw std::invalid_argument("voxelDownsample: leaf must be positive");
  internal::VoxelAccumulator voxels(leaf, points.size());
  for (const Eigen::Vector3f& p : points) voxels.add(p);
  return std::move(voxels).finish();
}

}  // namespace sgtllc
