// KITTI scans: a .bin (x y z intensity float32 records) and its .label (a uint32 or one byte per point).
// Input layout: byte 0 chooses where the rest splits into the .bin part and the .label part, so one input
// exercises readKittiBin, readLabelFile and the point/label count check of readLabeledScan in every label format.
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
  const size_t label_bytes = rest.size() - split;
  for (const LabelFormat format : {LabelFormat::kAuto, LabelFormat::kUint32, LabelFormat::kUint8}) {
    fuzz::readsOrRejects([&] {
      const LabeledCloud cloud = io::readLabeledScan(bin.path(), label.path(), format);
      const size_t n = cloud.points.size();
      fuzz::require(cloud.labels.size() == n, "as many labels as points");
      fuzz::require(label_bytes == n || label_bytes == 4 * n, "one byte or 4 a point");
      fuzz::require(format != LabelFormat::kUint8 || label_bytes == n, "uint8: one byte a point");
      fuzz::require(format != LabelFormat::kUint32 || label_bytes == 4 * n, "uint32: 4 bytes a point");
      const bool bytewise = format == LabelFormat::kUint8 || label_bytes != 4 * n;
      if (bytewise) {
        for (size_t i = 0; i < cloud.labels.size(); ++i) {
          fuzz::require(cloud.labels[i] == static_cast<uint8_t>(rest[split + i]), "a byte is its id");
        }
      }
    });
    // The count-only reader, for a scan as long as the .bin part would be.
    fuzz::readsOrRejects([&] {
      const size_t points = split / 16;
      fuzz::require(io::readLabelFile(label.path(), points, format).size() == points, "one label per point");
    });
  }
  return 0;
}
