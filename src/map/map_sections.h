// The payload parsers of a map file's sections (docs/map-format.md, "Layout"): each reads one section's payload
// from a Reader into Parts, bounds-checking every count and value.
#pragma once

#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "map_bytes.h"
#include "sgtllc/database.h"
#include "sgtllc/footprint.h"
#include "sgtllc/map/map.h"

namespace sgtllc::map::detail {

/// Sections as decoded, before they make a map.
struct Parts {
  std::optional<ConfigFields> config;
  std::optional<std::vector<std::string>> names;
  std::optional<std::vector<Eigen::Matrix4d>> poses;
  std::optional<std::vector<std::vector<Node>>> nodes;
  std::optional<std::pair<uint32_t, std::vector<float>>> keys;  // dimension, row-major keys
  std::optional<IvfState> ivf;                                   // a trained inverted file (retrieval.method ivf)
  std::optional<std::vector<Footprint>> footprints;              // one per frame (empty ones where none)
  std::optional<std::vector<Sight>> sights;                      // one per frame (empty ones where none)
  std::optional<std::vector<MapSession>> sessions;               // the drives merged into the map
};

struct SectionKind {
  std::string_view tag;
  void (*read)(Reader&, Parts&);
};

/// The section of @p tag this version reads, or nullptr (a section it skips).
const SectionKind* findSection(std::string_view tag);

}  // namespace sgtllc::map::detail
