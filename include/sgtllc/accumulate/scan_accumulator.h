/// @file scan_accumulator.h
/// @brief Superimposing consecutive scans of a narrow, sparse sensor (Livox Mid-70 and the like) before node
///        extraction: each new scan is merged with the N − 1 scans before it, moved into its frame by their poses.
///
/// The paper evaluates the MCD Mid-70 sequences on ~10 superimposed scans (following STD); the simulator does the
/// same in memory (sim/simulator.h, Simulator::merge). This is the same operation for real data: poses come from
/// an odometry or from ground truth, the core never reads them from files. Points and labels stay paired.
#pragma once

#include <cstddef>
#include <deque>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/types.h"

namespace sgtllc {

/// Scans given oldest first, each with its pose T_world_scan, merged in the frame of the last one:
/// p_newest = (T_world_newest⁻¹ · T_world_scan) · p. The newest scan's points are copied unchanged; every other
/// scan's rotation and translation are rounded to float once and applied in float (as the simulator does), so
/// the result is bit-reproducible. Output order: the scans in the given order, each in its own point order.
/// Throws sgtllc::Error if the counts differ, a scan's labels do not match its points, or a pose is not finite.
LabeledCloud mergeScans(const std::vector<const LabeledCloud*>& scans,
                        const std::vector<Eigen::Isometry3d>& T_world_scan);

/// A bounded buffer of the last N raw scans and their poses. add() returns the new scan merged with the N − 1
/// before it (fewer for the first frames of a sequence). At most N scans are ever held, so the memory is
/// N × (16 bytes per point: 12 for x, y, z in float and 4 for the label) plus N poses, whatever the sequence length.
class ScanAccumulator {
 public:
  /// @p scans: N, the scans merged into each frame, 1..kMaxScans (1 = every frame as it is).
  explicit ScanAccumulator(int scans);

  static constexpr int kMaxScans = 1000;

  /// Adds @p scan taken at @p T_world_scan (any fixed world frame; LiDAR frame of the scan), drops the oldest
  /// scan if N are held already, and returns mergeScans() of the held scans. Throws sgtllc::Error like
  /// mergeScans(); the buffer is unchanged then.
  LabeledCloud add(LabeledCloud scan, const Eigen::Isometry3d& T_world_scan);

  int capacity() const { return capacity_; }
  /// Scans held now (≤ capacity()).
  size_t size() const { return held_.size(); }
  /// Points held now, over all scans.
  size_t points() const;
  /// Bytes of the held points and labels (16 per point), the buffer's memory apart from fixed overheads.
  size_t bytes() const;
  /// Forgets every scan (a new sequence).
  void clear() { held_.clear(); }

 private:
  struct Held {
    LabeledCloud cloud;
    Eigen::Isometry3d T_world_scan;
  };
  int capacity_;
  std::deque<Held> held_;
};

}  // namespace sgtllc
