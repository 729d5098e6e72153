/// @file footprint_cells.h
/// @brief Where a footprint's occupied cells land in another frame's grid under a pose: the walk that the
///        footprint check (footprintOverlap) and the footprint search (bestFootprintShift) share (internal).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "sgtllc/footprint.h"

namespace sgtllc::internal {

/// Calls @p f(mi, mj) with the grid cell (column, row; same cell size and half-width as @p query) in which each
/// occupied cell of @p query, its centre at the sensor's height, lands under @p T_match_query, for the cells that
/// land within 0.8 of the grid's half-width of the other sensor: away from the grid's edge, where that sensor saw
/// little. Set bits only, word by word, lowest first (a footprint is mostly empty); a NaN pose lands nothing.
template <typename F>
void forEachLandingCell(const Footprint& query, const Eigen::Matrix4d& T_match_query, F&& f) {
  const int side = 2 * query.half;
  const double cell = query.cell;
  const double reach = 0.8 * query.half * cell;
  const Eigen::Matrix3d R = T_match_query.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = T_match_query.topRightCorner<3, 1>();
  for (size_t w = 0; w < query.bits.size(); ++w) {
    for (uint64_t word = query.bits[w]; word != 0; word &= word - 1) {
      const size_t k = w * 64 + static_cast<size_t>(__builtin_ctzll(word));
      const int i = static_cast<int>(k / static_cast<size_t>(side));
      const int j = static_cast<int>(k % static_cast<size_t>(side));
      const Eigen::Vector3d p((i - query.half + 0.5) * cell, (j - query.half + 0.5) * cell, 0.0);
      const Eigen::Vector3d m = R * p + t;
      if (!(m.head<2>().norm() <= reach)) continue;
      f(static_cast<int>(std::floor(m.x() / cell)) + query.half,
        static_cast<int>(std::floor(m.y() / cell)) + query.half);
    }
  }
}

}  // namespace sgtllc::internal
