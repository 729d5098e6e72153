// The options of relocalizing a sequence in a loaded map, for `sgtllc localize` and `sgtllc eval --map`
// (docs/relocalization.md); the relocalizing itself is pipeline::localizeSequence.
#pragma once

#include <optional>

#include <CLI/CLI.hpp>

#include "sgtllc/map/relocalization_tracker.h"
#include "sgtllc/pipeline/localization.h"

namespace sgtllc::cli {

/// The tracking options of `--track` (the defaults of map::TrackingOptions), or none without it.
std::optional<map::TrackingOptions> trackingOption(bool track);
/// Adds `--track` to a command that relocalizes a sequence (localize, eval --map).
void addTrackOption(CLI::App* cmd, bool* track);

using Hit = pipeline::LocalizedFrame;

}  // namespace sgtllc::cli
