// Encoding the map file format (docs/map-format.md; map_decode.cpp reads it). Every multi-byte value is little-endian; the writer and
// reader copy host words, so a big-endian host is refused at compile time rather than writing other files.
#include "sgtllc/map/map_format.h"

#include <algorithm>
#include <optional>

#include "ivf_section.h"
#include "map_bytes.h"

namespace sgtllc::map {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the map format is little-endian and this code copies host words: port it before using a big-endian host");

namespace {

using namespace detail;  // put, putText, the header constants (map_bytes.h), encodeIvf (ivf_section.h)

uint32_t crc(std::string_view bytes) { return crc32Of(bytes); }

void putSection(std::string& out, std::string_view tag, const std::string& payload) {
  const size_t start = out.size();
  out.append(tag.data(), 4);
  put<uint32_t>(out, kSectionVersion);
  put<uint64_t>(out, payload.size());
  out += payload;
  put<uint32_t>(out, crc(std::string_view(out).substr(start)));
}

}  // namespace

std::string encodeMap(const Map& map, const std::string& source) {
  checkFrames(map, source);
  const FrameDatabase& db = map.database;
  const uint64_t n = static_cast<uint64_t>(db.size());
  std::string conf, names, poses, nodes, keys;
  put<uint32_t>(conf, static_cast<uint32_t>(map.config.size()));
  for (const auto& [key, value] : map.config) {
    putText(conf, key);
    putText(conf, value);
  }
  put<uint64_t>(names, n);
  for (const std::string& name : map.names) putText(names, name);
  if (map.hasPoses()) {
    put<uint64_t>(poses, n);
    for (const Eigen::Matrix4d& T : map.poses) {
      for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 4; ++col) put<double>(poses, T(row, col));
      }
    }
  }
  put<uint64_t>(nodes, n);
  for (int f = 0; f < db.size(); ++f) put<uint32_t>(nodes, static_cast<uint32_t>(db.nodes(f).size()));
  for (int f = 0; f < db.size(); ++f) {
    for (const Node& node : db.nodes(f)) {
      for (int k = 0; k < 3; ++k) put<double>(nodes, node.centre[k]);
      put<int32_t>(nodes, node.label);
    }
  }
  const uint32_t dim = n ? static_cast<uint32_t>(db.globalDimension()) : 1;
  put<uint32_t>(keys, dim);
  put<uint64_t>(keys, n);
  for (int f = 0; f < db.size(); ++f) keys.append(reinterpret_cast<const char*>(db.global(f)), sizeof(float) * dim);
  const std::optional<IvfState> state = db.ivfState();
  const std::string ivf = state ? encodeIvf(*state, dim) : std::string();
  std::string footprints;
  if (!map.footprints.empty()) {
    put<uint64_t>(footprints, n);
    for (const Footprint& f : map.footprints) {
      put<float>(footprints, f.empty() ? 0.0f : f.cell);
      put<int32_t>(footprints, f.empty() ? 0 : f.half);
      for (uint64_t word : f.bits) put<uint64_t>(footprints, word);
    }
  }
  // The sights go in a section of their own: a reader that predates them skips it and checks footprints only.
  std::string sights;
  const bool any_sight = std::any_of(map.footprints.begin(), map.footprints.end(),
                                     [](const Footprint& f) { return !f.sight.empty(); });
  if (any_sight) {
    put<uint64_t>(sights, n);
    for (const Footprint& f : map.footprints) {
      put<uint16_t>(sights, static_cast<uint16_t>(f.sight.low.size()));
      for (const std::vector<uint8_t>* layer : {&f.sight.low, &f.sight.high}) {
        sights.append(reinterpret_cast<const char*>(layer->data()), layer->size());
      }
    }
  }
  std::string body;
  body.reserve(conf.size() + names.size() + poses.size() + nodes.size() + keys.size() + ivf.size() +
               footprints.size() + sights.size() + 8 * 20);
  putSection(body, "CONF", conf);
  putSection(body, "FRMS", names);
  if (map.hasPoses()) putSection(body, "POSE", poses);
  putSection(body, "NODE", nodes);
  putSection(body, "KEYS", keys);
  if (state) putSection(body, "IVFS", ivf);
  if (!footprints.empty()) putSection(body, "FTPR", footprints);
  if (!sights.empty()) putSection(body, "SGHT", sights);

  std::string out(kMagic);
  put<uint32_t>(out, kFormatVersion);
  put<uint32_t>(out, 4 + (map.hasPoses() ? 1 : 0) + (state ? 1 : 0) + (footprints.empty() ? 0 : 1) + (sights.empty() ? 0 : 1));
  put<uint64_t>(out, kHeaderBytes + body.size());
  put<uint64_t>(out, fingerprint(map.config));
  put<uint32_t>(out, 0);  // flags: none so far
  put<uint32_t>(out, crc(out));
  out.reserve(out.size() + body.size());
  out += body;
  return out;
}


}  // namespace sgtllc::map
