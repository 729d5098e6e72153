// PCD files (ascii, binary and binary_compressed data; io::readPcd, and io::readPcdPoints without labels).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fuzz_support.h"
#include "sgtllc/io/pcd.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("cloud.pcd");
  file.write(fuzz::bytesOf(data, size));
  std::vector<Eigen::Vector3f> labelled;
  const bool read_labelled = fuzz::readsOrRejects([&] {
    const LabeledCloud cloud = io::readPcd(file.path());
    fuzz::require(cloud.points.size() == cloud.labels.size(), "as many labels as points");
    labelled = cloud.points;
  });
  // The points-only read needs a subset of the fields: where the labelled read succeeds it must too, with the same
  // points to the bit (NaN coordinates are kept).
  const bool read_points = fuzz::readsOrRejects([&] {
    const std::vector<Eigen::Vector3f> points = io::readPcdPoints(file.path());
    fuzz::require(points.size() <= size, "no more points than input bytes");
    if (read_labelled) {
      fuzz::require(points.size() == labelled.size() &&
                        (points.empty() || std::memcmp(points.data(), labelled.data(), points.size() * sizeof(Eigen::Vector3f)) == 0),
                    "the points-only read gives the labelled read's points");
    }
  });
  fuzz::require(!read_labelled || read_points, "a file read with labels is read without them too");
  return 0;
}
