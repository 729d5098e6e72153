// SemanticKITTI sequence layout: DIR/velodyne/NNNNNN.bin beside DIR/labels/NNNNNN.label.
#include "sgtllc/io/sequence.h"

#include <algorithm>
#include <filesystem>

#include "sgtllc/io/kitti.h"

namespace sgtllc::io {
namespace {

namespace fs = std::filesystem;

/// Regular `*.bin` files of @p velodyne, sorted by file name (so frame i of a zero-padded sequence is NNNNNN = i).
std::vector<fs::path> listScans(const fs::path& velodyne) {
  std::error_code ec;
  if (!fs::is_directory(velodyne, ec)) {
    throw Error(velodyne.string() + ": no such directory (expected a SemanticKITTI sequence: velodyne/*.bin)");
  }
  std::vector<fs::path> scans;
  fs::directory_iterator it(velodyne, ec);
  if (ec) throw Error("cannot list " + velodyne.string() + ": " + ec.message());
  for (const fs::directory_entry& entry : it) {
    if (entry.path().extension() == ".bin" && entry.is_regular_file(ec)) scans.push_back(entry.path());
  }
  if (scans.empty()) throw Error(velodyne.string() + ": no .bin scans");
  std::sort(scans.begin(), scans.end(), [](const fs::path& a, const fs::path& b) {
    return a.filename().native() < b.filename().native();
  });
  return scans;
}

}  // namespace

SequenceDir::SequenceDir(const std::string& dir, const SequenceLabels& labels) : dir_(dir), format_(labels.format) {
  const fs::path root(dir);
  const std::vector<fs::path> scans = listScans(root / "velodyne");
  const fs::path label_dir = labels.dir.empty() ? root / "labels" : fs::path(labels.dir);
  std::error_code ec;
  if (labels.read && !labels.dir.empty() && !fs::is_directory(label_dir, ec)) {
    throw Error(labels.dir + ": no such label folder (expected NNNNNN.label files)");
  }
  std::string first_missing;
  size_t missing = 0;
  for (const fs::path& scan : scans) {
    bins_.push_back(scan.string());
    if (!labels.read) continue;
    const fs::path label = label_dir / fs::path(scan.stem()).concat(".label");
    if (!fs::is_regular_file(label, ec)) {
      if (missing++ == 0) first_missing = label.string();
    }
    labels_.push_back(label.string());
  }
  if (missing > 0) {
    throw Error(first_missing + ": missing label file (" + std::to_string(missing) + " of " +
                std::to_string(scans.size()) + " scans in " + (root / "velodyne").string() + " have no label)");
  }
}

std::string SequenceDir::frameName(size_t i) const { return fs::path(binPath(i)).stem().string(); }

LabeledCloud SequenceDir::load(size_t i) const {
  if (labels_.empty()) {
    LabeledCloud cloud;
    cloud.points = readKittiBin(binPath(i));
    return cloud;
  }
  return readLabeledScan(binPath(i), labelPath(i), format_);
}

}  // namespace sgtllc::io
