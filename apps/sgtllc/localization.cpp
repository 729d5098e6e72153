#include "localization.h"

#include <unordered_map>

#include "sgtllc/io/quote.h"

namespace sgtllc::cli {
namespace {

bool sameNodes(const std::vector<Node>& a, const std::vector<Node>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k) {
    if (a[k].label != b[k].label || a[k].centre != b[k].centre) return false;
  }
  return true;
}

}  // namespace

std::optional<map::TrackingOptions> trackingOption(bool track) {
  if (!track) return std::nullopt;
  return map::TrackingOptions{};
}

void addTrackOption(CLI::App* cmd, bool* track) {
  cmd->add_flag("--track", *track,
                "the frames are one stream: a weaker verified answer (score > 0.2) is accepted when it lies within "
                "3 m + 2 m per frame of the last accepted one, within 10 frames (docs/relocalization.md)");
}

std::vector<Hit> localizeSequence(const pipeline::FrameSource& source, const map::Relocalizer& relocalizer,
                                  const std::string& query_name, const std::string& map_path, int threads,
                                  const std::optional<map::TrackingOptions>& tracking,
                                  const std::function<void(size_t, const Hit&)>& on_hit) {
  std::optional<map::RelocalizationTracker> tracker;
  if (tracking) tracker.emplace(relocalizer, *tracking);
  const map::Map& m = relocalizer.map();
  std::unordered_map<std::string, int> map_frames;
  for (int f = 0; f < m.size(); ++f) map_frames.emplace(m.names[static_cast<size_t>(f)], f);
  std::vector<Hit> hits;
  pipeline::streamFrames(source, threads, [&](size_t index, pipeline::LoadedFrame& frame) {
    // Two sessions that both number their frames 000000, … do not clash: only the same name with the same nodes.
    const auto same = map_frames.find(source.name(index));
    if (same != map_frames.end() && sameNodes(frame.nodes, m.database.nodes(same->second))) {
      const std::string name = io::escapeContent(source.name(index), io::kNameBytes);  // a file name
      throw Error(query_name + ": frame " + name + " is frame " + name + " of map " +
                  map_path + " (same name, same nodes): the query sequence is the map's own session. Localize "
                  "another session of the same place, or build the map from another one");
    }
    // streamFrames calls in frame order, so the tracker sees the stream as it was recorded.
    Hit& h = hits.emplace_back(
        Hit{source.name(index), "",
            tracker ? tracker->localize(std::move(frame.nodes), std::move(frame.footprint))
                    : relocalizer.localize(std::move(frame.nodes), std::move(frame.footprint))});
    h.r.search.timing.extraction_ms = frame.extraction_ms;
    if (h.r.map_frame >= 0) h.map_frame = m.names[static_cast<size_t>(h.r.map_frame)];
    on_hit(index, h);
  });
  return hits;
}

}  // namespace sgtllc::cli
