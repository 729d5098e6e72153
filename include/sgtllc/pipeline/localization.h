/// @file localization.h
/// @brief Relocalizing every frame of a sequence in a loaded map, in order (docs/relocalization.md;
///        map/relocalizer.h): what `sgtllc localize` and `sgtllc eval --map` run.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sgtllc/map/relocalization_tracker.h"
#include "sgtllc/map/relocalizer.h"
#include "sgtllc/pipeline/frame_source.h"

namespace sgtllc::pipeline {

/// One query frame's answer.
struct LocalizedFrame {
  std::string query, map_frame;  ///< map_frame empty: no candidate passed verification
  map::Relocalization r;
};

/// Relocalizes every frame of @p source in @p relocalizer's map, in order, loading frames in parallel batches
/// (streamFrames; the answers do not depend on @p threads). @p on_frame sees each answer as it comes. With
/// @p tracking, the frames are one stream (map::RelocalizationTracker), else each is answered alone. Throws
/// sgtllc::Error naming @p query_name and @p map_path when a query frame is the map frame of the same name with the
/// same nodes: the map's own session fed back, whose every answer would be that frame itself.
std::vector<LocalizedFrame> localizeSequence(const FrameSource& source, const map::Relocalizer& relocalizer,
                                             const std::string& query_name, const std::string& map_path, int threads,
                                             const std::optional<map::TrackingOptions>& tracking,
                                             const std::function<void(size_t, const LocalizedFrame&)>& on_frame);

}  // namespace sgtllc::pipeline
