/// @file footprint.h
/// @brief A frame's footprint: the horizontal cells its structure occupies, and how well two footprints overlap
///        under a verified pose (docs/algorithm.md §7.7).
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/labels.h"
#include "sgtllc/sight.h"
#include "sgtllc/types.h"

namespace sgtllc {

/// The cells of a square grid (side VerificationConfig::footprint_cell, centred on the sensor, reaching
/// footprint_radius) that hold at least one point of a stable class other than terrain: walls, fences, vegetation,
/// trunks, poles and signs seen from above. A few nodes can agree by chance where two places have similar
/// objects; the structure around them rarely does. 3,200 bytes at the defaults (160 × 160 cells of 0.5 m), and
/// the sight's 720 with the seen-through check on.
struct Footprint {
  float cell = 0.0f;           ///< cell side (m)
  int half = 0;                ///< the grid has 2·half cells a side; cell (i, j) covers [(i − half)·cell, …)
  std::vector<uint64_t> bits;  ///< row-major occupancy, (2·half)² bits; empty: no footprint (node input, maps)
  /// true: every cell next to an occupied one is set as well (dilateFootprint), the form a stored frame keeps so
  /// that each query cell costs one look-up instead of nine.
  bool dilated = false;
  /// How far the sensor saw (sight.h): the footprint says where the structure is, the sight where it is not.
  /// Empty unless verification.max_seen_through < 1.
  Sight sight;

  bool empty() const { return bits.empty(); }
  /// The 64-bit words of the bits of a grid of 2·@p half cells a side.
  static size_t words(int half);
  bool occupied(int i, int j) const;
  size_t bytes() const { return bits.size() * sizeof(uint64_t) + sight.bytes(); }
};

/// The footprint of a labelled scan (points in the sensor frame, ids read through @p labels); empty when
/// verification.min_footprint_overlap is 0. A pure function of its inputs. NodeExtractor::extract gives the same
/// footprint from its own pass over the points.
Footprint computeFootprint(const LabeledCloud& cloud, const LabelMap& labels, const VerificationConfig& config);

/// Sets a footprint's cells point by point: what computeFootprint does for each point, for a pass over the points
/// that does more than that (node extraction's class split), so that a scan is read once.
class FootprintMarker {
 public:
  /// The grid of @p config; enabled() is false when verification.min_footprint_overlap is 0.
  explicit FootprintMarker(const VerificationConfig& config);
  bool enabled() const { return enabled_; }
  /// An empty footprint of this grid (no cell set; the sight not yet computed); an empty Footprint if !enabled().
  Footprint grid() const;
  /// Sets the cell of point @p q of stable class @p c in @p bits (Footprint::bits of grid()): terrain, points beyond
  /// the radius and points with a non-finite x or y set nothing.
  void mark(const Eigen::Vector3f& q, int c, std::vector<uint64_t>& bits) const {
    // Terrain is ground: its cells say only that there is ground, which two different streets share.
    if (c < 0 || c == kTerrain) return;
    if (!(q.x() * q.x() + q.y() * q.y() < r2_)) return;  // also drops NaN
    const int i = static_cast<int>(std::floor(q.x() / cell_)) + half_;
    const int j = static_cast<int>(std::floor(q.y() / cell_)) + half_;
    if (i < 0 || j < 0 || i >= 2 * half_ || j >= 2 * half_) return;
    const size_t k = static_cast<size_t>(i) * static_cast<size_t>(2 * half_) + static_cast<size_t>(j);
    bits[k >> 6] |= uint64_t{1} << (k & 63u);
  }

 private:
  bool enabled_ = false;
  float cell_ = 1.0f;
  int half_ = 0;
  float r2_ = 0.0f;
};

/// Completes a footprint whose cells a FootprintMarker set: its sight, when verification.max_seen_through < 1.
void finishFootprint(const std::vector<Eigen::Vector3f>& points, const VerificationConfig& config, Footprint* f);

/// @p f with each occupied cell's eight neighbours set too, and Footprint::dilated; @p f itself if empty or dilated.
Footprint dilateFootprint(const Footprint& f);

/// How two footprints agree under a pose.
struct FootprintOverlap {
  int compared = 0;    ///< occupied query cells that land well inside the match's grid (within 0.8 of its radius)
  double share = 0.0;  ///< of those, the share that land on or next to an occupied match cell; 0 if none
  SeenThrough seen;    ///< the two frames' sights under the pose (sight.h)
};

/// Moves the centre of every occupied cell of @p query by @p T_match_query (p_match = T · p_query, the query's
/// cell centres taken at the sensor's height) and counts those that fall on an occupied cell of @p match or one of
/// its eight neighbours (one cell of slack for the pose error and the grid's phase). Both must have one grid; @p match
/// may be dilated (the same result, faster), @p query must not be.
FootprintOverlap footprintOverlap(const Footprint& query, const Footprint& match, const Eigen::Matrix4d& T_match_query);

}  // namespace sgtllc
