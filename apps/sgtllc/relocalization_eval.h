// `sgtllc eval S2 --map MAP`: the relocalization protocol (docs/relocalization.md).
#pragma once

#include <optional>
#include <string>

#include "sgtllc/config.h"
#include "sgtllc/map/relocalization_tracker.h"

namespace sgtllc::cli {

/// Relocalizes every frame of the sequence @p sequence (or of the node files in @p nodes, with @p sequence's
/// poses; @p labels_dir: --labels-dir) in the map file @p map_path and prints the protocol's metrics against the map's stored poses and the
/// sequence's poses.txt + calib.txt, as text or (@p json) one JSON object. Throws sgtllc::Error naming the file
/// when the map has no poses or the sequence no ground truth. @p tracking: the frames are one stream (--track).
void evalRelocalization(const std::string& map_path, const std::string& sequence, const std::string& nodes,
                        const std::string& labels_dir, const Config& config, bool json,
                        const std::optional<map::TrackingOptions>& tracking);

}  // namespace sgtllc::cli
