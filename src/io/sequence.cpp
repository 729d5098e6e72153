// Sequence folders (README "Your own data"): SemanticKITTI's DIR/velodyne/NNNNNN.bin beside DIR/labels/NNNNNN.label,
// or a folder of .bin, .pcd or .ply scans whose labels are in the files or in DIR/labels/.
#include "sgtllc/io/sequence.h"

#include <algorithm>
#include <array>
#include <filesystem>

namespace sgtllc::io {
namespace {

namespace fs = std::filesystem;

/// The per-point field a PCD or PLY scan carries its labels in (pcl::PointXYZL's name).
constexpr const char* kLabelField = "label";

struct ScanList {
  fs::path dir;
  ScanFormat format = ScanFormat::kKittiBin;
  std::vector<fs::path> scans;
};

/// The scans of @p root: `root/velodyne/*` if that folder exists, else `root/*`; regular files of one scan format,
/// sorted by file name (so frame i of a zero-padded sequence is NNNNNN = i).
ScanList listScans(const fs::path& root) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) {
    throw Error(root.string() + ": no such directory (expected a sequence: velodyne/*.bin, or .bin, .pcd or .ply "
                                "scans in the folder itself)");
  }
  ScanList list;
  list.dir = fs::is_directory(root / "velodyne", ec) ? root / "velodyne" : root;
  std::array<std::vector<fs::path>, 3> by_format;
  fs::directory_iterator it(list.dir, ec);
  if (ec) throw Error("cannot list " + list.dir.string() + ": " + ec.message());
  for (const fs::directory_entry& entry : it) {
    const std::optional<ScanFormat> format = scanFormatOf(entry.path().string());
    if (format && entry.is_regular_file(ec)) by_format[static_cast<size_t>(*format)].push_back(entry.path());
  }
  std::string found;
  for (size_t f = 0; f < by_format.size(); ++f) {
    if (by_format[f].empty()) continue;
    if (!list.scans.empty()) found += ", ";
    found += std::to_string(by_format[f].size()) + " " + scanExtension(static_cast<ScanFormat>(f));
    if (list.scans.empty()) list.format = static_cast<ScanFormat>(f);
    list.scans.insert(list.scans.end(), by_format[f].begin(), by_format[f].end());
  }
  if (list.scans.empty()) {
    throw Error(list.dir.string() + ": no scans (.bin, .pcd or .ply)" +
                (list.dir == root ? " and no velodyne/ folder" : std::string()));
  }
  if (list.scans.size() != by_format[static_cast<size_t>(list.format)].size()) {
    throw Error(list.dir.string() + ": mixes scan formats (" + found + " files); a sequence folder holds one format");
  }
  std::sort(list.scans.begin(), list.scans.end(), [](const fs::path& a, const fs::path& b) {
    return a.filename().native() < b.filename().native();
  });
  return list;
}

}  // namespace

SequenceDir::SequenceDir(const std::string& dir, const SequenceLabels& labels)
    : dir_(dir), label_format_(labels.format) {
  const fs::path root(dir);
  const ScanList list = listScans(root);
  scan_dir_ = list.dir.string();
  format_ = list.format;
  for (const fs::path& scan : list.scans) scans_.push_back(scan.string());
  if (!labels.read) return;
  // A network's label folder, when given, wins over any label field; else a PCD or PLY folder whose first scan
  // has a label field keeps its labels in the files (every scan must have it: load() says which does not).
  labels_in_scans_ = labels.dir.empty() && format_ != ScanFormat::kKittiBin && scanHasField(scans_[0], kLabelField);
  if (labels_in_scans_) return;
  const fs::path label_dir = labels.dir.empty() ? root / "labels" : fs::path(labels.dir);
  std::error_code ec;
  if (!labels.dir.empty() && !fs::is_directory(label_dir, ec)) {
    throw Error(labels.dir + ": no such label folder (expected NNNNNN.label files)");
  }
  std::string first_missing;
  size_t missing = 0;
  for (const fs::path& scan : list.scans) {
    const fs::path label = label_dir / fs::path(scan.stem()).concat(".label");
    if (!fs::is_regular_file(label, ec)) {
      if (missing++ == 0) first_missing = label.string();
    }
    labels_.push_back(label.string());
  }
  if (missing > 0 && labels.require_all) {
    const std::string no_field = format_ == ScanFormat::kKittiBin
                                     ? ""
                                     : std::string(", and ") + fs::path(scans_[0]).filename().string() +
                                           " has no '" + kLabelField + "' field";
    throw Error(first_missing + ": missing label file (" + std::to_string(missing) + " of " +
                std::to_string(scans_.size()) + " scans in " + scan_dir_ + " have no label" + no_field + ")");
  }
}

std::string SequenceDir::frameName(size_t i) const { return fs::path(scanPath(i)).stem().string(); }

LabeledCloud SequenceDir::load(size_t i) const {
  if (labels_in_scans_) return readScanWithLabelField(scanPath(i), kLabelField);
  if (labels_.empty()) {
    LabeledCloud cloud;
    cloud.points = readScanPoints(scanPath(i));
    return cloud;
  }
  std::error_code ec;
  if (!fs::is_regular_file(labelPath(i), ec)) throw Error(labelPath(i) + ": missing label file");
  return readScanWithLabelFile(scanPath(i), labelPath(i), label_format_);
}

}  // namespace sgtllc::io
