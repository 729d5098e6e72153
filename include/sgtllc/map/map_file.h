/// @file map_file.h
/// @brief Map files: read one section at a time, written atomically, that never replaces a file unasked (docs/map-format.md).
#pragma once

#include <string>

#include "sgtllc/config.h"
#include "sgtllc/io/output_file.h"
#include "sgtllc/map/map.h"
#include "sgtllc/map/map_format.h"

namespace sgtllc::map {

/// Writes @p map to @p path through a temporary file and a rename (io::writeFileAtomically): readers never see a
/// partial map, and with io::Overwrite::kRefuse an existing file is kept. Throws sgtllc::Error naming @p path.
void writeMapFile(const std::string& path, const Map& map, io::Overwrite overwrite);

/// Reads the map file @p path one section at a time, as decodeMap() checks bytes (never holding the file whole:
/// loading takes about 1.1 times the file's size), its frames searched with @p config's retrieval.method, then
/// checks it against @p config (checkCompatible). Throws sgtllc::Error naming the file if it cannot be read, is a
/// directory or runs out of memory, and MapError naming it for a bad, old or incompatible map, or one whose header
/// declares more bytes than this machine's memory (MapProblem::kTooLarge, before any allocation).
Map readMapFile(const std::string& path, const Config& config, MapLayout* layout = nullptr);

/// The same without a configuration to check against (`sgtllc map info`).
Map readMapFile(const std::string& path, MapLayout* layout = nullptr);

}  // namespace sgtllc::map
