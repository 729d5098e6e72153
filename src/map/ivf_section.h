// The IVFS section of a map file: a trained inverted file (retrieval.method ivf; docs/map-format.md).
#pragma once

#include <cstdint>
#include <string>

#include "map_bytes.h"
#include "sgtllc/database.h"

namespace sgtllc::map::detail {

/// The payload: lists, frames trained on, key length, the centroids, then one list per indexed frame.
std::string encodeIvf(const IvfState& state, uint32_t dim);
/// Reads it back, every count and list number bounds-checked (Reader::fail: a corrupted map).
IvfState readIvfState(Reader& r);

}  // namespace sgtllc::map::detail
