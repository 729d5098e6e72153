/// @file refinement_stats.h
/// @brief What the online fine registration (registration.online; docs/registration.md) did over a sequence: how
///        many declared loops it refined, how many fell back to the SVD pose and why, its time and its store.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sgtllc/registration/icp.h"

namespace sgtllc::eval {

/// Number of RefinementStatus values (kConverged … kMovedTooFar).
inline constexpr int kRefinementStatuses = 6;

struct RefinementStats {
  bool enabled = false;   ///< registration.online was on
  int refined = 0;        ///< declared loops whose pose was refined (a status below)
  int used = 0;           ///< ... whose refined pose replaced the SVD pose (converged or max_iterations)
  /// Loops by status, indexed by RefinementStatus: the fallbacks are the entries past kMaxIterations.
  std::array<int, kRefinementStatuses> by_status{};
  /// Per frame, all frames: StageTimes::refinement_ms (making the frame's clouds, and the ICP when it closes a loop).
  double ms_per_frame_median = 0.0;
  double ms_per_frame_mean = 0.0;
  double cloud_bytes_per_frame = 0.0;  ///< the cloud store at the end / frames (CloudStore::bytes)

  int fallbacks() const { return refined - used; }
};

/// The statistics from each frame's refinement status (nullopt: the frame closed no refined loop), its
/// refinement time, and the store's final size.
RefinementStats refinementStats(bool enabled, const std::vector<std::optional<RefinementStatus>>& statuses,
                                const std::vector<double>& refinement_ms, size_t cloud_bytes);

/// One line for `sgtllc eval`, e.g. "refinement: 801 loops refined, 799 used (converged 790, max_iterations 9);
/// kept the SVD pose 2 (too_few_points 0, degenerate 0, low_fitness 0, moved_too_far 2); 1.52 ms per frame median
/// (mean 3.10); cloud store 59880 bytes per frame".
std::string refinementLine(const RefinementStats& s);

}  // namespace sgtllc::eval
