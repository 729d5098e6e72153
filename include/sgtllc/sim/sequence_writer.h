/// @file sequence_writer.h
/// @brief Writes a simulated sequence in the SemanticKITTI layout, with ground truth and a realism summary.
///
/// DIR/velodyne/%06d.bin, DIR/labels/%06d.label, DIR/poses.txt (cam0 poses, KITTI convention), DIR/calib.txt
/// (KITTI 00's P0–P3 and Tr), DIR/times.txt, DIR/loop_pairs.txt (`query candidate label`, 1 = within 3 m, 0 = farther
/// than 20 m), DIR/odometry.txt (a drifting odometry estimate in the format and frame of poses.txt; odometry.h),
/// DIR/simulation.txt (the settings, so a second session can rebuild the world; manifest.h), a second session's
/// DIR/cross_session.txt (the nearest first-session frame of each frame; cross_session.h) and two bird's-eye-view
/// PNGs. Only these files are written; nothing is ever deleted. A second session's poses (and odometry) are in the
/// first session's frame 0, so its poses.txt does not start at the identity.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "sgtllc/sim/loop_pairs.h"
#include "sgtllc/sim/odometry.h"
#include "sgtllc/sim/simulator.h"
#include "sgtllc/types.h"

namespace sgtllc::sim {

struct WriteOptions {
  std::string dir;          ///< output folder (created if missing)
  int threads = 1;          ///< frames computed in parallel; the bytes written do not depend on it
  bool force = false;       ///< write into a folder that is not empty (overwriting only the files listed above)
  bool previews = true;     ///< write preview_scan.png and preview_trajectory.png
  int node_stats_every = 10;  ///< count graph nodes (default clustering) on every k-th frame; 0 = never
  OdometryNoise odometry;     ///< noise of odometry.txt (seeded by the simulator's seed; odometry.h)
};

/// What was written, for a person to judge its realism.
struct SequenceStats {
  int frames = 0;
  std::vector<uint32_t> points;                   ///< per frame
  std::map<uint16_t, uint64_t> class_points;      ///< written (noisy) semantic id → points over all frames
  std::vector<std::array<int, kNumPaperClasses>> nodes;       ///< nodes per class of the sampled frames (written labels)
  std::vector<std::array<int, kNumPaperClasses>> true_nodes;  ///< the same with ground-truth labels
  size_t positives = 0, negatives = 0;            ///< loop pairs written
  int query_frames = 0;       ///< frames with a loop candidate within 3 m
  int opposite_queries = 0;   ///< ... of which at least one candidate faces the other way (yaw difference > 135°)
  std::map<VisitKind, int> frames_by_kind;        ///< frames driven per visit kind
  std::vector<double> lane_shift_offsets;         ///< frames on lane-shift revisits: distance to the nearest earlier frame (m)
  double path_length = 0.0;          ///< distance driven, sum of the frame-to-frame LiDAR displacements (m)
  double odometry_end_error = 0.0;   ///< odometry.txt's LiDAR position error at the last frame (m)
  int cross_near = 0;  ///< second session: frames with a first-session frame within 3 m (relocalization positives)
  int cross_far = 0;   ///< second session: frames with none within 20 m (where a relocalization is false)
};

/// Refuses a path that is a file, or a folder that is not empty unless @p force; touches nothing.
void checkOutputDir(const std::string& dir, bool force);
/// checkOutputDir(), then creates DIR, velodyne/ and labels/.
void prepareOutputDir(const std::string& dir, bool force);

/// Writes the whole sequence; @p progress (may be empty) is called with the number of frames written so far.
SequenceStats writeSequence(const Simulator& sim, const WriteOptions& options,
                            const std::function<void(int)>& progress = {});

/// The LiDAR poses T_lidar0_lidari of a written sequence, read back from poses.txt and calib.txt with the
/// project's readers (so loop pairs agree exactly with what a reader of the files computes).
std::vector<Eigen::Matrix4d> readBackLidarPoses(const std::string& dir);

}  // namespace sgtllc::sim
