/// @file fec_search.h
/// @brief fastEuclideanClustering with its dense-neighbourhood threshold exposed (internal; for tests).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace sgtllc::internal {

/// Candidates (points in a seed's block of 2r cells) above which fastEuclideanClustering first searches a seed's
/// neighbours ring by ring on a fine grid instead of scanning them all; the public function passes
/// max(8 · max_neighbors, kDenseCandidates). Either search finds the same neighbours.
inline constexpr size_t kDenseCandidates = 256;

/// fastEuclideanClustering (clustering.h) with seeds whose block holds more than @p dense_candidates points
/// searched ring by ring first. The clusters do not depend on @p dense_candidates (tests lower it to reach the rings).
std::vector<std::vector<uint32_t>> fastEuclideanClustering(const std::vector<Eigen::Vector3f>& points, double radius,
                                                          int max_neighbors, int min_size, size_t dense_candidates);

}  // namespace sgtllc::internal
