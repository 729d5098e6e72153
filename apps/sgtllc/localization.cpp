#include "localization.h"

#include <unordered_map>

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

std::vector<Hit> localizeSequence(const eval::FrameSource& source, const map::Relocalizer& relocalizer,
                                  const std::string& query_name, const std::string& map_path, int threads,
                                  const std::function<void(size_t, const Hit&)>& on_hit) {
  const map::Map& m = relocalizer.map();
  std::unordered_map<std::string, int> map_frames;
  for (int f = 0; f < m.size(); ++f) map_frames.emplace(m.names[static_cast<size_t>(f)], f);
  std::vector<Hit> hits;
  eval::streamFrames(source, threads, [&](size_t index, eval::LoadedFrame& frame) {
    // Two sessions that both number their frames 000000, … do not clash: only the same name with the same nodes.
    const auto same = map_frames.find(source.name(index));
    if (same != map_frames.end() && sameNodes(frame.nodes, m.database.nodes(same->second))) {
      throw Error(query_name + ": frame " + source.name(index) + " is frame " + source.name(index) + " of map " +
                  map_path + " (same name, same nodes): the query sequence is the map's own session. Localize "
                  "another session of the same place, or build the map from another one");
    }
    Hit& h = hits.emplace_back(Hit{source.name(index), "", relocalizer.localize(std::move(frame.nodes))});
    h.r.search.timing.extraction_ms = frame.extraction_ms;
    if (h.r.map_frame >= 0) h.map_frame = m.names[static_cast<size_t>(h.r.map_frame)];
    on_hit(index, h);
  });
  return hits;
}

}  // namespace sgtllc::cli
