/// @file loop_pairs.h
/// @brief Ground-truth loop pairs from poses, in the format of the SSC pair lists: `query candidate label`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/io/output_file.h"

namespace sgtllc::sim {

struct LoopPair {
  int query = 0;      ///< the later frame
  int candidate = 0;  ///< the earlier frame
  bool loop = false;  ///< true: within positive_distance; false: farther than negative_distance
};

struct LoopPairOptions {
  double positive_distance = 3.0;   ///< m (3-D, between LiDAR positions): a loop at or below this
  double negative_distance = 20.0;  ///< m: a non-loop above this; pairs in between are left out
  int min_gap = 50;                 ///< frames between query and candidate (the detector skips the last 50 too)
  int negatives_per_positive = 1;   ///< as SSC's neg_1 lists ...
  int min_negatives = 100;          ///< ... but at least this many (when that many exist)
  uint64_t seed = 1;                ///< which negatives are drawn
};

/// Every positive pair and a random sample of negatives, sorted by query then candidate. @p lidar_poses are
/// T_lidar0_lidari (or any common frame).
std::vector<LoopPair> loopPairs(const std::vector<Eigen::Matrix4d>& lidar_poses, const LoopPairOptions& options);

/// Writes `%06d %06d %d` lines (io::writeFileAtomically); throws sgtllc::Error `cannot write PATH: REASON`.
void writeLoopPairs(const std::string& path, const std::vector<LoopPair>& pairs,
                    io::Overwrite overwrite = io::Overwrite::kReplace);

}  // namespace sgtllc::sim
