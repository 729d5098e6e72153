// KITTI ground truth: poses.txt (io::readKittiPoses) and calib.txt (io::readKittiCalibTr), then the LiDAR-frame
// poses eval::GroundTruth builds from them. The same bytes go to both readers, since a calib.txt and a poses.txt
// share their number syntax.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/kitti.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("poses.txt");
  file.write(fuzz::bytesOf(data, size));
  std::vector<Eigen::Matrix4d> poses;
  Eigen::Matrix4d Tr = Eigen::Matrix4d::Identity();
  fuzz::readsOrRejects([&] { poses = io::readKittiPoses(file.path()); });
  for (const Eigen::Matrix4d& P : poses) {
    fuzz::require(P.allFinite() && P.row(3) == Eigen::RowVector4d(0, 0, 0, 1), "finite poses, last row 0 0 0 1");
  }
  if (!fuzz::readsOrRejects([&] { Tr = io::readKittiCalibTr(file.path()); })) return 0;
  fuzz::require(Tr.allFinite(), "finite calibration");
  fuzz::readsOrRejects([&] { io::lidarPoses(poses, Tr); });
  return 0;
}
