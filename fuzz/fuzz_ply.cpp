// PLY files (ascii, binary little- and big-endian; io::readPly, and io::readPlyPoints without labels).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/io/ply_read.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("cloud.ply");
  file.write(fuzz::bytesOf(data, size));
  fuzz::checkCloudReaders(
      size, [&] { return io::readPly(file.path()); }, [&] { return io::readPlyPoints(file.path()); });
  return 0;
}
