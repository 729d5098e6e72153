/// @file squared_distance.h
/// @brief The one squared L2 distance of retrieval keys (internal): the linear scan, the kd-tree's re-check and
///        the inverted file all rank frames with it, so they agree on every distance.
#pragma once

namespace sgtllc::internal {

/// Squared L2 distance with eight independent partial sums: the compiler may vectorise it (a single running sum
/// is a strict float dependency chain it must not reorder), and the fixed summation order keeps results
/// identical from run to run.
inline float squaredDistance(const float* a, const float* b, int dim) {
  constexpr int kLanes = 8;
  float lane[kLanes] = {};
  int d = 0;
  for (; d + kLanes <= dim; d += kLanes) {
    for (int l = 0; l < kLanes; ++l) {
      const float diff = a[d + l] - b[d + l];
      lane[l] += diff * diff;
    }
  }
  float sum = 0.0f;
  for (; d < dim; ++d) sum += (a[d] - b[d]) * (a[d] - b[d]);
  for (float v : lane) sum += v;
  return sum;
}

}  // namespace sgtllc::internal
