/// @file footprint_search.h
/// @brief The horizontal shift of a verified pose under which two footprints agree best (docs/algorithm.md §7.9).
#pragma once

#include <Eigen/Core>

#include "sgtllc/footprint.h"

namespace sgtllc {

/// A shift of a pose's translation and how the footprints agree with and without it.
struct FootprintShift {
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  ///< added to the pose's x and y (m, match frame)
  /// The query's occupied cells judged: those footprintOverlap compares under the unshifted pose; 0 = no search.
  int compared = 0;
  double share = 0.0;            ///< of those, the share on or next to an occupied match cell under the shifted pose
  double unshifted_share = 0.0;  ///< share under the pose itself
};

/// Among the shifts of @p T_match_query's translation by whole footprint cells, up to @p radius (m) in x and in y,
/// the one under which the most of the query's compared cells land on or next to the match's structure (the
/// share of footprintOverlap, over the cells it compares under the unshifted pose). A coarse pass every third cell,
/// on an even sample of at most 256 of the query's cells, then the cells around its best on all of them: with
/// footprintOverlap's cell of slack a peak cannot fall between two coarse shifts. That slack also lets a shift and
/// its neighbours agree equally well; the fine pass gives such a tie to the shift whose eight neighbours agree best
/// (the middle of the plateau), then to the shorter shift, the lower x, the lower y, so that the answer is a pure
/// function of its inputs whether @p match is stored dilated or not.
///
/// Segments along a straight street (walls, fences, hedges, ground) are centred on the part each scan sees, which
/// moves with the sensor, and trees planted at even spacing match their neighbours: the nodes can then agree on a
/// pose a few metres short along the street. The structure around them rarely does (BENCHMARKS.md "Footprint
/// search"). Returns a zero shift with compared 0 when the footprints cannot be compared or fewer than
/// @p min_compared cells are, and a zero shift (share = unshifted_share) when no coarse shift gains half of
/// @p min_gain on the sample: the caller then would not move the pose, and the fine pass is spared.
FootprintShift bestFootprintShift(const Footprint& query, const Footprint& match, const Eigen::Matrix4d& T_match_query,
                                  double radius, int min_compared, double min_gain = 0.0);

}  // namespace sgtllc
