// KITTI scans: a .bin (x y z intensity float32 records) and its SemanticKITTI .label (uint32 per point).
// Input layout: byte 0 chooses where the rest splits into the .bin part and the .label part, so one input
// exercises readKittiBin, readLabelFile and the point/label count check of readLabeledScan.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/kitti.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile bin("scan.bin"), label("scan.label");
  if (size == 0) return 0;
  const std::string_view rest = fuzz::bytesOf(data + 1, size - 1);
  const size_t split = rest.size() * data[0] / 255;
  bin.write(rest.substr(0, split));
  label.write(rest.substr(split));

  fuzz::readsOrRejects([&] {
    std::vector<float> intensity;
    const std::vector<Eigen::Vector3f> points = io::readKittiBin(bin.path(), &intensity);
    fuzz::require(points.size() * 16 == split && intensity.size() == points.size(), "one point per 16 bytes");
  });
  fuzz::readsOrRejects([&] {
    fuzz::require(io::readLabelFile(label.path()).size() * 4 == rest.size() - split, "one label per 4 bytes");
  });
  fuzz::readsOrRejects([&] {
    const LabeledCloud cloud = io::readLabeledScan(bin.path(), label.path());
    fuzz::require(cloud.points.size() == cloud.labels.size(), "as many labels as points");
  });
  return 0;
}
