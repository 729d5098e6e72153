// Shared by the scan-folder suites (test_io_scan_folders.cpp, test_cli_scan_folders.cpp): writers of PCD and PLY
// scans built from the formats' specs (PCL's PCD v0.7, Turk's PLY), independent of the library's readers, and the
// conversion of a KITTI-layout sequence into a folder of them.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sgtllc/io/kitti.h"
#include "sgtllc/types.h"

namespace sgtllc::test {

enum class ScanFile { kPcdAscii, kPcdBinary, kPlyAscii, kPlyBinary };

inline const char* extensionOf(ScanFile kind) {
  return kind == ScanFile::kPcdAscii || kind == ScanFile::kPcdBinary ? ".pcd" : ".ply";
}

/// Writes @p cloud (with a uint32 `label` field when @p with_labels) in @p kind. Ascii floats take 9 significant
/// digits, which read back to the same float.
inline void writeScanFile(const std::string& path, const LabeledCloud& cloud, ScanFile kind, bool with_labels) {
  const size_t n = cloud.points.size();
  std::string out;
  const bool pcd = kind == ScanFile::kPcdAscii || kind == ScanFile::kPcdBinary;
  const bool ascii = kind == ScanFile::kPcdAscii || kind == ScanFile::kPlyAscii;
  if (pcd) {
    out = std::string("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z") +
          (with_labels ? " label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n" : "\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n") +
          "WIDTH " + std::to_string(n) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(n) +
          "\nDATA " + (ascii ? "ascii" : "binary") + "\n";
  } else {
    out = std::string("ply\nformat ") + (ascii ? "ascii" : "binary_little_endian") +
          " 1.0\ncomment written by the sgtllc tests\nelement vertex " + std::to_string(n) +
          "\nproperty float x\nproperty float y\nproperty float z\n" + (with_labels ? "property uint label\n" : "") +
          "end_header\n";
  }
  char buf[96];
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = cloud.points[i];
    if (ascii) {
      int len = std::snprintf(buf, sizeof(buf), "%.9g %.9g %.9g", p.x(), p.y(), p.z());
      if (with_labels) len += std::snprintf(buf + len, sizeof(buf) - len, " %u", cloud.labels[i]);
      out.append(buf, static_cast<size_t>(len)).push_back('\n');
    } else {
      out.append(reinterpret_cast<const char*>(p.data()), 12);  // the test host is little-endian
      if (with_labels) out.append(reinterpret_cast<const char*>(&cloud.labels[i]), 4);
    }
  }
  std::ofstream(path, std::ios::binary) << out;
}

/// Rewrites the KITTI-layout sequence @p from (velodyne/*.bin + labels/*.label) as @p to: scans of @p kind in
/// `to/velodyne/` if @p in_velodyne, else in `to` itself, with their labels in a label field; poses.txt and
/// calib.txt are copied.
inline void convertSequence(const std::filesystem::path& from, const std::filesystem::path& to, ScanFile kind,
                            bool in_velodyne) {
  namespace fs = std::filesystem;
  const fs::path scans = in_velodyne ? to / "velodyne" : to;
  fs::create_directories(scans);
  for (const auto& entry : fs::directory_iterator(from / "velodyne")) {
    const std::string stem = entry.path().stem().string();
    const LabeledCloud cloud =
        io::readLabeledScan(entry.path().string(), (from / "labels" / (stem + ".label")).string());
    writeScanFile((scans / (stem + extensionOf(kind))).string(), cloud, kind, true);
  }
  for (const char* name : {"poses.txt", "calib.txt"}) {
    if (fs::exists(from / name)) fs::copy_file(from / name, to / name);
  }
}

}  // namespace sgtllc::test
