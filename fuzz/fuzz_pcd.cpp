// PCD files (ascii, binary and binary_compressed data; io::readPcd, and io::readPcdPoints without labels).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/pcd.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("cloud.pcd");
  file.write(fuzz::bytesOf(data, size));
  fuzz::checkCloudReaders(
      size, [&] { return io::readPcd(file.path()); }, [&] { return io::readPcdPoints(file.path()); });
  return 0;
}
