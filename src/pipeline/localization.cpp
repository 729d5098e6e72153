#include "sgtllc/pipeline/localization.h"

#include <unordered_map>

#include "sgtllc/io/quote.h"

namespace sgtllc::pipeline {
namespace {

bool sameNodes(const std::vector<Node>& a, const std::vector<Node>& b) {
  if (a.size() != b.size()) return false;
  for (size_t k = 0; k < a.size(); ++k) {
    if (a[k].label != b[k].label || a[k].centre != b[k].centre) return false;
  }
  return true;
}

}  // namespace

std::vector<LocalizedFrame> localizeSequence(const FrameSource& source, const map::Relocalizer& relocalizer,
                                             const std::string& query_name, const std::string& map_path, int threads,
                                             const std::optional<map::TrackingOptions>& tracking,
                                             const std::function<void(size_t, const LocalizedFrame&)>& on_frame) {
  std::optional<map::RelocalizationTracker> tracker;
  if (tracking) tracker.emplace(relocalizer, *tracking);
  const map::Map& m = relocalizer.map();
  std::unordered_map<std::string, int> map_frames;
  for (int f = 0; f < m.size(); ++f) map_frames.emplace(m.names[static_cast<size_t>(f)], f);
  std::vector<LocalizedFrame> hits;
  streamFrames(source, threads, [&](size_t index, LoadedFrame& frame) {
    // Two sessions that both number their frames 000000, … do not clash: only the same name with the same nodes.
    const auto same = map_frames.find(source.name(index));
    if (same != map_frames.end() && sameNodes(frame.nodes, m.database.nodes(same->second))) {
      const std::string name = io::escapeContent(source.name(index), io::kNameBytes);  // a file name
      throw Error(query_name + ": frame " + name + " is frame " + name + " of map " +
                  map_path + " (same name, same nodes): the query sequence is the map's own session. Localize "
                  "another session of the same place, or build the map from another one");
    }
    // streamFrames calls in frame order, so the tracker sees the stream as it was recorded.
    LocalizedFrame& h = hits.emplace_back(
        LocalizedFrame{source.name(index), "",
            tracker ? tracker->localize(std::move(frame.nodes), std::move(frame.footprint))
                    : relocalizer.localize(std::move(frame.nodes), std::move(frame.footprint))});
    h.r.search.timing.extraction_ms = frame.extraction_ms;
    if (h.r.map_frame >= 0) h.map_frame = m.names[static_cast<size_t>(h.r.map_frame)];
    on_frame(index, h);
  });
  return hits;
}

}  // namespace sgtllc::pipeline
