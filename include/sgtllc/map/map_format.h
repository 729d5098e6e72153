/// @file map_format.h
/// @brief A Map as bytes: the versioned, checksummed, little-endian format of docs/map-format.md. No files here
///        (map_file.h reads and writes them).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sgtllc/map/map.h"

namespace sgtllc::map {

/// The format version this sgtllc writes and the only one it reads (docs/map-format.md, "Versions"): it rises
/// whenever what a map records changes, including the configuration fields mapConfig() stores. Older maps (what each
/// version lacked: that table) are refused as MapProblem::kOlderVersion.
inline constexpr uint32_t kFormatVersion = 5;

/// One section of a map file as found by decodeMap.
struct SectionInfo {
  std::string tag;       ///< four letters: CONF, FRMS, POSE, NODE, KEYS, IVFS, FTPR, SGHT (or one this version does not know)
  uint32_t version = 0;  ///< the section's own version
  uint64_t bytes = 0;    ///< the whole section: its 16-byte head, payload and 4-byte checksum
  bool known = true;     ///< false: skipped (a section added by a later writer that readers may ignore)
};

/// What decodeMap saw besides the map itself (for `sgtllc map info`).
struct MapLayout {
  uint32_t format_version = 0;
  uint64_t fingerprint = 0;  ///< of the map's configuration fields (fingerprint())
  uint64_t file_bytes = 0;
  std::vector<SectionInfo> sections;
};

/// The bytes of @p map (checkFrames first: throws MapError(kInvalid) naming @p source).
std::string encodeMap(const Map& map, const std::string& source = "map");

/// The map in @p bytes, its frames searched with @p method. Checks everything before it returns: throws
/// MapError naming @p source and saying which problem (not a map, truncated, corrupted, older or newer version),
/// never a partly filled map. Does not compare the configuration (checkCompatible does). Fills @p layout if given.
Map decodeMap(std::string_view bytes, const std::string& source, RetrievalMethod method = RetrievalMethod::kBruteForce,
              MapLayout* layout = nullptr);

}  // namespace sgtllc::map
