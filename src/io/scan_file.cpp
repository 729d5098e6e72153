// Dispatch on a scan's extension, so sequence folders (sequence.cpp) and single scans (`sgtllc pair`, `label`) read
// the same formats with the same messages (README "Data formats").
#include "sgtllc/io/scan_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "sgtllc/io/kitti.h"
#include "sgtllc/io/pcd.h"
#include "sgtllc/io/ply_read.h"

namespace sgtllc::io {
namespace {

ScanFormat requireFormat(const std::string& path) {
  const std::optional<ScanFormat> format = scanFormatOf(path);
  if (!format) {
    throw Error(path + ": unknown scan format '" + std::filesystem::path(path).extension().string() +
                "' (expected a KITTI .bin, a .pcd or a .ply)");
  }
  return *format;
}

}  // namespace

std::optional<ScanFormat> scanFormatOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".bin") return ScanFormat::kKittiBin;
  if (ext == ".pcd") return ScanFormat::kPcd;
  if (ext == ".ply") return ScanFormat::kPly;
  return std::nullopt;
}

const char* scanExtension(ScanFormat format) {
  switch (format) {
    case ScanFormat::kKittiBin: return ".bin";
    case ScanFormat::kPcd: return ".pcd";
    case ScanFormat::kPly: return ".ply";
  }
  return "";
}

std::vector<Eigen::Vector3f> readScanPoints(const std::string& path) {
  switch (requireFormat(path)) {
    case ScanFormat::kKittiBin: return readKittiBin(path);
    case ScanFormat::kPcd: return readPcdPoints(path);
    case ScanFormat::kPly: return readPlyPoints(path);
  }
  return {};
}

bool scanHasField(const std::string& path, const std::string& name) {
  std::vector<std::string> fields;
  switch (requireFormat(path)) {
    case ScanFormat::kKittiBin: return false;
    case ScanFormat::kPcd: fields = pcdFieldNames(path); break;
    case ScanFormat::kPly: fields = plyVertexProperties(path); break;
  }
  return std::find(fields.begin(), fields.end(), name) != fields.end();
}

LabeledCloud readScanWithLabelField(const std::string& path, const std::string& label_field) {
  switch (requireFormat(path)) {
    case ScanFormat::kKittiBin:
      throw Error(path + ": a KITTI .bin scan has no label field; its labels are in a .label file");
    case ScanFormat::kPcd: return readPcd(path, label_field);
    case ScanFormat::kPly: return readPly(path, label_field);
  }
  return {};
}

LabeledCloud readScanWithLabelFile(const std::string& path, const std::string& label_path, LabelFormat format) {
  if (requireFormat(path) == ScanFormat::kKittiBin) return readLabeledScan(path, label_path, format);
  LabeledCloud cloud;
  cloud.points = readScanPoints(path);
  cloud.labels = readLabelFileOf(label_path, path, cloud.points.size(), format);
  return cloud;
}

}  // namespace sgtllc::io
