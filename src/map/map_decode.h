// Decoding a map from a stream of bytes (docs/map-format.md, "Reading"): decodeMap() over memory, readMapFile()
// over a file, one section at a time.
#pragma once

#include <cstdint>
#include <string>

#include "map_bytes.h"
#include "sgtllc/map/map_format.h"

namespace sgtllc::map::detail {

/// decodeMap() of the bytes of @p bytes; a map whose header declares more than @p loadable_bytes is refused
/// (MapProblem::kTooLarge) before anything is allocated for it.
Map decodeMapFrom(ByteSource& bytes, const std::string& source, RetrievalMethod method, MapLayout* layout,
                  uint64_t loadable_bytes);

}  // namespace sgtllc::map::detail
