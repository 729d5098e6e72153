/// @file frame_source.h
/// @brief Frames of a sequence as graph nodes: from a SemanticKITTI folder (scans + labels) or from node files,
///        and the streaming loop that feeds them to the online detector.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sgtllc/accumulate/scan_accumulator.h"
#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/node_extraction.h"

namespace sgtllc::pipeline {

/// Most scans FrameSource::accumulate and PipelineOptions::accumulate merge into one frame.
constexpr int kMaxAccumulatedScans = ScanAccumulator::kMaxScans;

/// One frame reduced to nodes, with what it cost.
struct LoadedFrame {
  std::vector<Node> nodes;
  ExtractionStats stats;       ///< point bookkeeping (node files: unknown ids in unknown_label_points)
  double load_ms = 0.0;        ///< reading files
  double extraction_ms = 0.0;  ///< points → nodes (0 for node files)
  RegistrationClouds clouds;   ///< for registration.online (scans only; empty otherwise)
  Footprint footprint;         ///< for the footprint check (scans only; empty otherwise)
  double clouds_ms = 0.0;      ///< making them
  double accumulate_ms = 0.0;  ///< merging the previous scans in (FrameSource::accumulate; 0 otherwise)
  size_t buffer_bytes = 0;     ///< memory of the accumulation buffer after this frame (ScanAccumulator::bytes)
};

/// How FrameSource::semanticKitti finds a sequence's labels.
struct FrameSourceOptions {
  /// Folder of NAME.label files read instead of `DIR/labels/` or a PCD/PLY label field (`--labels-dir`: a
  /// segmentation network's predictions). Not used with labeller.source geometric, which reads no labels.
  std::string labels_dir;
};

/// An ordered list of frames that can be loaded independently (and so in parallel).
class FrameSource {
 public:
  /// The scans of a sequence folder (io::SequenceDir: `DIR/velodyne/NAME.bin`, or `.bin`, `.pcd` or `.ply`
  /// scans in DIR itself) with their labels (`DIR/labels/NAME.label`, options.labels_dir/NAME.label, or a PCD/PLY
  /// label field), clustered with @p config. With config.labeller.source geometric only the scans are read and
  /// the geometric labeller gives the classes (docs/labeller.md).
  static FrameSource semanticKitti(const std::string& dir, const Config& config,
                                   const FrameSourceOptions& options = {});
  /// `DIR/NAME.txt` node files (one `x y z label` row per node), labels mapped with @p config.labels.
  static FrameSource nodeFiles(const std::string& dir, const Config& config);

  size_t size() const { return names_.size(); }
  /// File stem of frame i ("000052").
  const std::string& name(size_t i) const { return names_.at(i); }
  /// The frame number its name encodes (the line of poses.txt), or −1 if the name is not a number.
  long number(size_t i) const;
  /// Reads frame i. Throws sgtllc::Error naming the file on bad input. Safe to call from several threads.
  /// When accumulating, it reads the scans frame i merges (streamSequence reads each scan once instead).
  LoadedFrame load(size_t i) const;

  /// From now on frame i is raw scan i merged with the @p scans − 1 scans before it, moved into its frame by
  /// @p T_world_scan (one LiDAR-frame pose per frame; accumulate/scan_accumulator.h). Scans only: throws
  /// sgtllc::Error for node files, a pose count other than size(), or @p scans outside 1..kMaxAccumulatedScans.
  void accumulate(int scans, std::vector<Eigen::Isometry3d> T_world_scan);
  /// Scans merged into each frame (1: none).
  int accumulated() const { return scans_; }

 private:
  std::vector<std::string> names_;
  std::function<LoadedFrame(size_t)> loader_;
  // Scans only, the two halves of loader_: reading raw scan i, and reducing a (merged) scan to a frame.
  std::function<LabeledCloud(size_t)> read_;
  std::function<LoadedFrame(const LabeledCloud&)> reduce_;
  int scans_ = 1;
  std::vector<Eigen::Isometry3d> poses_;

  friend void streamFrames(const FrameSource&, int, const std::function<void(size_t, LoadedFrame&)>&);
};

/// Loads every frame of @p source in parallel batches on @p threads threads and hands them to @p on_frame one by
/// one, in order, on the calling thread (so what it does cannot depend on the thread count). The first frame that
/// fails to load throws its sgtllc::Error once the frames before it were handed over. An accumulating source reads
/// its raw scans in parallel, merges them in order (one ScanAccumulator: each scan is read once, at most N held)
/// and reduces the merged scans in parallel.
void streamFrames(const FrameSource& source, int threads, const std::function<void(size_t, LoadedFrame&)>& on_frame);

/// Feeds every frame of @p source to @p detector in order. Frames are read and clustered in parallel batches on
/// @p threads threads (a pure function of each frame); the detector then sees them one by one, so results are
/// the same at any thread count (streamFrames). @p on_frame receives each frame's index, loaded data (nodes moved out) and result.
void streamSequence(const FrameSource& source, LoopDetector& detector, int threads,
                    const std::function<void(size_t, const LoadedFrame&, const FrameResult&)>& on_frame);

}  // namespace sgtllc::pipeline
