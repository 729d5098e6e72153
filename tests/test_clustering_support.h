// Shared by the clustering suites (test_voxel_fec.cpp, test_node_extraction.cpp): point-list type and a
// brute-force voxel grid reference.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::test {

using Cloud = std::vector<Eigen::Vector3f>;

/// Voxel sums and counts, voxels in order of first appearance (std::map keyed on the floor of p / leaf).
struct RefVoxels {
  std::vector<Eigen::Vector3d> sums;
  std::vector<uint32_t> counts;
};

inline RefVoxels voxelReference(const Cloud& pts, double leaf) {
  std::map<std::array<long, 3>, size_t> index;
  RefVoxels ref;
  for (const auto& p : pts) {
    const std::array<long, 3> key = {static_cast<long>(std::floor(p.x() / leaf)),
                                     static_cast<long>(std::floor(p.y() / leaf)),
                                     static_cast<long>(std::floor(p.z() / leaf))};
    const auto [it, added] = index.emplace(key, ref.sums.size());
    if (added) {
      ref.sums.emplace_back(Eigen::Vector3d::Zero());
      ref.counts.push_back(0);
    }
    ref.sums[it->second] += p.cast<double>();
    ++ref.counts[it->second];
  }
  return ref;
}

}  // namespace sgtllc::test
