/// @file sequence.h
/// @brief A SemanticKITTI-layout sequence directory: velodyne/NNNNNN.bin with labels/NNNNNN.label.
#pragma once

#include <string>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

/// Where the per-point labels of a sequence's scans are read from.
struct SequenceLabels {
  bool read = true;     ///< false: scans only (labeller.source geometric); load() gives no labels
  std::string dir;      ///< folder of NAME.label files (a network's predictions/); "" = `DIR/labels`
  LabelFormat format = LabelFormat::kAuto;  ///< uint32 or one byte a point (LabelConfig::format; readLabelFile)
};

/// The scans of one sequence and their label files. Only file names are collected at construction; scans are read
/// on demand by load().
class SequenceDir {
 public:
  /// Lists the regular files `dir/velodyne/*.bin` in ascending file-name order (byte-wise, so zero-padded KITTI names
  /// sort by frame number) and pairs each with `dir/labels/NAME.label` (or `labels.dir/NAME.label`; none if
  /// !labels.read). Other files are ignored. Throws sgtllc::Error if `velodyne/` is missing or has no .bin file,
  /// if labels.dir is not a folder, or if any scan has no label file; that message names the first missing
  /// label file and says how many of the scans have none.
  explicit SequenceDir(const std::string& dir, const SequenceLabels& labels = {});

  /// Number of scans.
  size_t size() const { return bins_.size(); }
  /// The directory as given to the constructor.
  const std::string& dir() const { return dir_; }
  /// Path of scan i (`dir/velodyne/NAME.bin`); throws std::out_of_range if i >= size().
  const std::string& binPath(size_t i) const { return bins_.at(i); }
  /// Path of the labels of scan i (`dir/labels/NAME.label`); throws std::out_of_range if i >= size() or the
  /// labels are not read.
  const std::string& labelPath(size_t i) const { return labels_.at(i); }
  /// File stem of frame i ("000052").
  std::string frameName(size_t i) const;
  /// Reads frame i (scan + labels, counts checked; see readLabeledScan). Without labels (SequenceLabels::read
  /// false) the cloud's labels are empty.
  LabeledCloud load(size_t i) const;

 private:
  std::string dir_;
  std::vector<std::string> bins_;
  std::vector<std::string> labels_;
  LabelFormat format_ = LabelFormat::kAuto;
};

}  // namespace sgtllc::io
