/// @file frame_source.h
/// @brief Frames of a sequence as graph nodes: from a SemanticKITTI folder (scans + labels) or from node files,
///        and the streaming loop that feeds them to the online detector.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/node_extraction.h"

namespace sgtllc::eval {

/// One frame reduced to nodes, with what it cost.
struct LoadedFrame {
  std::vector<Node> nodes;
  ExtractionStats stats;       ///< point bookkeeping (node files: unknown ids in unknown_label_points)
  double load_ms = 0.0;        ///< reading files
  double extraction_ms = 0.0;  ///< points → nodes (0 for node files)
  RegistrationClouds clouds;   ///< for registration.online (scans only; empty otherwise)
  double clouds_ms = 0.0;      ///< making them
};

/// How FrameSource::semanticKitti finds a sequence's labels.
struct FrameSourceOptions {
  /// Folder of NAME.label files read instead of `DIR/labels/` (`--labels-dir`: a segmentation network's
  /// predictions). Not used with labeller.source geometric, which reads no labels.
  std::string labels_dir;
};

/// An ordered list of frames that can be loaded independently (and so in parallel).
class FrameSource {
 public:
  /// `DIR/velodyne/NAME.bin` + `DIR/labels/NAME.label` (or options.labels_dir/NAME.label), clustered with
  /// @p config. With config.labeller.source geometric only the scans are read and the geometric labeller gives
  /// the classes (docs/labeller.md).
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
  LoadedFrame load(size_t i) const { return loader_(i); }

 private:
  std::vector<std::string> names_;
  std::function<LoadedFrame(size_t)> loader_;
};

/// Feeds every frame of @p source to @p detector in order. Frames are read and clustered in parallel batches on
/// @p threads threads (a pure function of each frame); the detector then sees them one by one, so results are
/// the same at any thread count. @p on_frame receives each frame's index, loaded data (nodes moved out) and result.
void streamSequence(const FrameSource& source, LoopDetector& detector, int threads,
                    const std::function<void(size_t, const LoadedFrame&, const FrameResult&)>& on_frame);

}  // namespace sgtllc::eval
