#include "localization.h"

namespace sgtllc::cli {

std::optional<map::TrackingOptions> trackingOption(bool track) {
  if (!track) return std::nullopt;
  return map::TrackingOptions{};
}

void addTrackOption(CLI::App* cmd, bool* track) {
  cmd->add_flag("--track", *track,
                "the frames are one stream: a weaker verified answer (score > 0.2) is accepted when it lies within "
                "3 m + 2 m per frame of the last accepted one, within 10 frames (docs/relocalization.md)");
}

}  // namespace sgtllc::cli
