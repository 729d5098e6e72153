// Relocalizing every frame of a sequence in a loaded map, for `sgtllc localize` and `sgtllc eval --map`
// (issue 10; map/relocalizer.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sgtllc/eval/frame_source.h"
#include "sgtllc/map/relocalizer.h"

namespace sgtllc::cli {

/// One query frame's answer.
struct Hit {
  std::string query, map_frame;  ///< map_frame empty: no candidate passed verification
  map::Relocalization r;
};

/// Relocalizes every frame of @p source in @p relocalizer's map, in order, loading frames in parallel batches
/// (eval::streamFrames; the answers do not depend on config.threads). @p on_hit sees each answer as it comes.
/// Throws sgtllc::Error naming @p query_name and @p map_path when a query frame is the map frame of the same name
/// with the same nodes: the map's own session fed back, whose every answer would be that frame itself.
std::vector<Hit> localizeSequence(const eval::FrameSource& source, const map::Relocalizer& relocalizer,
                                  const std::string& query_name, const std::string& map_path, int threads,
                                  const std::function<void(size_t, const Hit&)>& on_hit);

}  // namespace sgtllc::cli
