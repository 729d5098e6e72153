// Relocalizing every frame of a sequence in a loaded map, for `sgtllc localize` and `sgtllc eval --map`
// (docs/relocalization.md; map/relocalizer.h).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/map/relocalization_tracker.h"
#include "sgtllc/map/relocalizer.h"

namespace sgtllc::cli {

/// The tracking options of `--track` (the defaults of map::TrackingOptions), or none without it.
std::optional<map::TrackingOptions> trackingOption(bool track);
/// Adds `--track` to a command that relocalizes a sequence (localize, eval --map).
void addTrackOption(CLI::App* cmd, bool* track);

/// One query frame's answer.
struct Hit {
  std::string query, map_frame;  ///< map_frame empty: no candidate passed verification
  map::Relocalization r;
};

/// Relocalizes every frame of @p source in @p relocalizer's map, in order, loading frames in parallel batches
/// (pipeline::streamFrames; the answers do not depend on config.threads). @p on_hit sees each answer as it comes.
/// With @p tracking, the frames are one stream (map::RelocalizationTracker; --track), else each is answered alone.
/// Throws sgtllc::Error naming @p query_name and @p map_path when a query frame is the map frame of the same name
/// with the same nodes: the map's own session fed back, whose every answer would be that frame itself.
std::vector<Hit> localizeSequence(const pipeline::FrameSource& source, const map::Relocalizer& relocalizer,
                                  const std::string& query_name, const std::string& map_path, int threads,
                                  const std::optional<map::TrackingOptions>& tracking,
                                  const std::function<void(size_t, const Hit&)>& on_hit);

}  // namespace sgtllc::cli
