// PCD files (ascii, binary and binary_compressed data; io::readPcd).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/pcd.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("cloud.pcd");
  file.write(fuzz::bytesOf(data, size));
  fuzz::readsOrRejects([&] {
    const LabeledCloud cloud = io::readPcd(file.path());
    fuzz::require(cloud.points.size() == cloud.labels.size(), "as many labels as points");
  });
  return 0;
}
