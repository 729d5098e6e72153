// Shared by the suites that read the bundled KITTI 00 scans (data/kitti/00): a scan with its labels, and a small
// sequence folder built from them. Apart from test_support.h, so that the suites that need no file formats do not
// link sgtllc_io.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sgtllc/io/kitti.h"
#include "test_support.h"

namespace sgtllc::test {

/// A bundled KITTI 00 scan with its SemanticKITTI labels, e.g. kittiScan("004501").
inline LabeledCloud kittiScan(const std::string& frame) {
  return io::readLabeledScan(dataPath("kitti/00/velodyne/" + frame + ".bin"),
                             dataPath("kitti/00/labels/" + frame + ".label"));
}

/// Writes a SemanticKITTI-layout sequence of 54 frames into @p dir: the real scans 52 and 88, 50 frames
/// without any stable class (one road point), 850, and 4501 (frame 53, a revisit of frame 0 2.96 m away).
/// poses.txt gives the real KITTI poses of the real scans and far-away poses (> 1 km) to the padding frames;
/// calib.txt is KITTI 00's.
inline void makePlantedSequence(const std::string& dir) {
  namespace fs = std::filesystem;
  fs::create_directories(fs::path(dir) / "velodyne");
  fs::create_directories(fs::path(dir) / "labels");
  const std::vector<Eigen::Matrix4d> kitti = io::readKittiPoses(dataPath("kitti/00/poses.txt"));
  std::ofstream poses(fs::path(dir) / "poses.txt");
  poses.precision(17);
  int index = 0;
  auto add = [&](const std::string& bin, const std::string& label, const Eigen::Matrix4d& pose) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d", index++);
    fs::copy_file(bin, fs::path(dir) / "velodyne" / (std::string(name) + ".bin"));
    fs::copy_file(label, fs::path(dir) / "labels" / (std::string(name) + ".label"));
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) poses << pose(r, c) << (r == 2 && c == 3 ? "\n" : " ");
    }
  };
  auto real = [&](int frame) {
    char name[16];
    std::snprintf(name, sizeof(name), "%06d", frame);
    add(dataPath("kitti/00/velodyne/" + std::string(name) + ".bin"),
        dataPath("kitti/00/labels/" + std::string(name) + ".label"), kitti.at(static_cast<size_t>(frame)));
  };
  real(52);
  real(88);
  const std::string one_bin = (fs::path(dir) / "one.bin").string(), one_label = (fs::path(dir) / "one.label").string();
  std::ofstream(one_bin, std::ios::binary).write("\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0", 16);
  const uint32_t road = 40;
  std::ofstream(one_label, std::ios::binary).write(reinterpret_cast<const char*>(&road), 4);
  for (int k = 0; k < 50; ++k) {
    Eigen::Matrix4d far = Eigen::Matrix4d::Identity();
    far(0, 3) = 2000.0 + 100.0 * k;
    add(one_bin, one_label, far);
  }
  fs::remove(one_bin);
  fs::remove(one_label);
  real(850);
  real(4501);
  fs::copy_file(dataPath("kitti/00/calib.txt"), fs::path(dir) / "calib.txt");
}

}  // namespace sgtllc::test
