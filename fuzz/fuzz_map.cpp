// Map files (map::readMapFile, docs/map-format.md): whatever is read must re-encode to a file that reads back to
// exactly the same map. Each input is read twice: as it is,
// and with its checksums recomputed, since a random mutation almost never passes the crc32s and the section
// parsers behind them would otherwise go untested.
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_support.h"
#include "sgtllc/map/map_file.h"

using namespace sgtllc;

namespace {

void setCrc(std::string& bytes, size_t begin, size_t end) {
  const uint32_t crc =
      static_cast<uint32_t>(crc32_z(0, reinterpret_cast<const Bytef*>(bytes.data() + begin), end - begin));
  std::memcpy(&bytes[end], &crc, 4);
}

/// @p bytes with the header's and every section's checksum recomputed, walking the declared lengths as far as
/// they stay inside the input (the rest is left as it is).
std::string withChecksums(std::string bytes) {
  if (bytes.size() < 40) return bytes;
  setCrc(bytes, 0, 36);
  for (size_t pos = 40; bytes.size() - pos >= 20;) {
    uint64_t payload;
    std::memcpy(&payload, &bytes[pos + 8], 8);
    if (payload > bytes.size() - pos - 20) break;
    setCrc(bytes, pos, pos + 16 + static_cast<size_t>(payload));
    pos += 20 + static_cast<size_t>(payload);
  }
  return bytes;
}

void readOne(const fuzz::ScratchFile& file, const std::string& bytes) {
  file.write(bytes);
  const size_t size = bytes.size();
  map::Map m;
  map::MapLayout layout;
  if (!fuzz::readsOrRejects([&] { m = map::readMapFile(file.path(), &layout); })) return;
  fuzz::require(layout.file_bytes == size, "the header's size is the file's");
  fuzz::require(m.names.size() == static_cast<size_t>(m.size()), "one name per frame");
  fuzz::require(m.poses.empty() || m.poses.size() == m.names.size(), "poses for all frames or none");
  // Re-encoding writes the canonical form (sections in order, no empty POSE, no unknown sections), which must
  // read back to the same map and encode to the same bytes again.
  const std::string again = map::encodeMap(m);
  const map::Map back = map::decodeMap(again, "again");
  fuzz::require(map::encodeMap(back) == again, "the canonical form is stable");
  fuzz::require(back.names == m.names && back.config == m.config, "names and configuration survive");
  fuzz::require(back.poses.size() == m.poses.size(), "poses survive");
  fuzz::require(back.sessions.size() == m.sessions.size(), "sessions survive");
  for (size_t s = 0; s < m.sessions.size(); ++s) {
    fuzz::require(back.sessions[s].name == m.sessions[s].name && back.sessions[s].first == m.sessions[s].first &&
                      back.sessions[s].frames == m.sessions[s].frames,
                  "sessions are exact");
  }
  for (size_t f = 0; f < m.poses.size(); ++f) fuzz::require(back.poses[f] == m.poses[f], "poses are exact");
  for (int f = 0; f < m.size(); ++f) {
    const auto& a = m.database.nodes(f);
    const auto& b = back.database.nodes(f);
    fuzz::require(a.size() == b.size(), "node counts survive");
    for (size_t k = 0; k < a.size(); ++k) {
      fuzz::require(a[k].centre == b[k].centre && a[k].label == b[k].label, "nodes are exact");
    }
    fuzz::require(std::memcmp(m.database.global(f), back.database.global(f),
                              sizeof(float) * static_cast<size_t>(m.database.globalDimension())) == 0,
                  "keys are exact");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("map.sgtmap");
  const std::string bytes(fuzz::bytesOf(data, size));
  readOne(file, bytes);
  readOne(file, withChecksums(bytes));
  return 0;
}
