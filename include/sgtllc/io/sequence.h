/// @file sequence.h
/// @brief A sequence directory: SemanticKITTI's velodyne/NNNNNN.bin with labels/NNNNNN.label, or a folder of
///        .bin, .pcd or .ply scans (labels in a label field or in labels/).
#pragma once

#include <string>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/io/scan_file.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

/// Where the per-point labels of a sequence's scans are read from.
struct SequenceLabels {
  bool read = true;     ///< false: scans only (labeller.source geometric); load() gives no labels
  std::string dir;      ///< folder of NAME.label files (a network's predictions/); "" = `DIR/labels`
  LabelFormat format = LabelFormat::kAuto;  ///< uint32 or one byte a point (LabelConfig::format; readLabelFile)
  /// true: every scan must have its label file, checked at construction (the error counts the missing ones);
  /// false: only the scans that are loaded, checked by load() (e.g. the pairs `repeatability --pair` names).
  bool require_all = true;
};

/// The scans of one sequence and their labels. Only file names are collected at construction (and the header of
/// the first scan of a PCD or PLY folder); scans are read on demand by load().
///
/// Layout (README "Your own data"): the scans are `dir/velodyne/*` if that folder exists (SemanticKITTI), else
/// the files of `dir` itself; they are the regular files named `*.bin` (KITTI), `*.pcd` or `*.ply` (extensions in
/// any letter case), one format a folder. Labels, unless !labels.read: from `labels.dir/NAME.label` when
/// labels.dir is given; else, for PCD and PLY scans whose first file has a `label` field, from that field of
/// every scan; else from `dir/labels/NAME.label`.
class SequenceDir {
 public:
  /// Lists the scans in ascending file-name order (byte-wise, so zero-padded KITTI names sort by frame number)
  /// and pairs each with its label file as above. Other files are ignored. Throws sgtllc::Error if `dir` is not a
  /// folder or holds no scans, if the scan folder mixes formats (the message names the folder and counts each),
  /// if labels.dir is not a folder, or if any scan has no label file; that message names the first missing label
  /// file and says how many of the scans have none.
  explicit SequenceDir(const std::string& dir, const SequenceLabels& labels = {});

  /// Number of scans.
  size_t size() const { return scans_.size(); }
  /// The directory as given to the constructor.
  const std::string& dir() const { return dir_; }
  /// The folder the scans were found in: `dir/velodyne` or `dir`.
  const std::string& scanDir() const { return scan_dir_; }
  /// The scans' format (one a sequence).
  ScanFormat format() const { return format_; }
  /// True when the labels come from the scans' own `label` field (PCD, PLY), not from label files.
  bool labelsInScans() const { return labels_in_scans_; }
  /// Path of scan i (`dir/velodyne/NAME.bin`, `dir/NAME.pcd`, …); throws std::out_of_range if i >= size().
  const std::string& scanPath(size_t i) const { return scans_.at(i); }
  /// scanPath(i), under its historical name (every scan was a .bin).
  const std::string& binPath(size_t i) const { return scanPath(i); }
  /// Path of the labels of scan i (`dir/labels/NAME.label`); throws std::out_of_range if i >= size() or no label
  /// files are read (!labels.read, or labelsInScans()).
  const std::string& labelPath(size_t i) const { return labels_.at(i); }
  /// File stem of frame i ("000052").
  std::string frameName(size_t i) const;
  /// Reads frame i (scan + labels, counts checked; see readScanWithLabelFile, readScanWithLabelField). Without
  /// labels (SequenceLabels::read false) the cloud's labels are empty.
  LabeledCloud load(size_t i) const;

 private:
  std::string dir_;
  std::string scan_dir_;
  ScanFormat format_ = ScanFormat::kKittiBin;
  bool labels_in_scans_ = false;
  std::vector<std::string> scans_;
  std::vector<std::string> labels_;
  LabelFormat label_format_ = LabelFormat::kAuto;
};

}  // namespace sgtllc::io
