// Map files (map::readMapFile, docs/map-format.md): whatever is read must re-encode to the same bytes when every
// section is known, and to a file that reads back to the same map otherwise.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "sgtllc/map/map_file.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("map.sgtmap");
  file.write(fuzz::bytesOf(data, size));
  map::Map m;
  map::MapLayout layout;
  if (!fuzz::readsOrRejects([&] { m = map::readMapFile(file.path(), &layout); })) return 0;
  fuzz::require(layout.file_bytes == size, "the header's size is the file's");
  fuzz::require(m.names.size() == static_cast<size_t>(m.size()), "one name per frame");
  fuzz::require(m.poses.empty() || m.poses.size() == m.names.size(), "poses for all frames or none");
  bool all_known = true;
  for (const map::SectionInfo& s : layout.sections) all_known = all_known && s.known;
  const std::string again = map::encodeMap(m);
  if (all_known) fuzz::require(again == fuzz::bytesOf(data, size), "a map re-encodes to its own bytes");
  fuzz::require(map::encodeMap(map::decodeMap(again, "again")) == again, "a re-encoded map reads back the same");
  return 0;
}
