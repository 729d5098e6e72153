// Encoding the map file format (docs/map-format.md; map_decode.cpp reads it). Every multi-byte value is little-endian; the writer and
// reader copy host words, so a big-endian host is refused at compile time rather than writing other files.
#include "sgtllc/map/map_format.h"

#include <algorithm>
#include <optional>

#include "ivf_section.h"
#include "map_bytes.h"
#include "map_encode.h"

namespace sgtllc::map {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the map format is little-endian and this code copies host words: port it before using a big-endian host");

namespace {

using namespace detail;  // put, putText, the header constants (map_bytes.h), encodeIvf (ivf_section.h), EncodedMap

uint32_t crc(std::string_view bytes) { return crc32Of(bytes); }

/// A section: head (tag, version, payload bytes), @p payload, then @p tail (views of memory held elsewhere: the
/// keys), then the crc32 of all of it.
void putSection(EncodedMap& out, std::string_view tag, std::string payload,
                const std::vector<std::string_view>& tail = {}) {
  uint64_t bytes = payload.size();
  for (std::string_view t : tail) bytes += t.size();
  std::string head(tag.data(), 4);
  put<uint32_t>(head, kSectionVersion);
  put<uint64_t>(head, bytes);
  uint32_t sum = crc32Of(payload, crc32Of(head));
  for (std::string_view t : tail) sum = crc32Of(t, sum);
  std::string end;
  put<uint32_t>(end, sum);
  out.own(std::move(head));
  out.own(std::move(payload));
  for (std::string_view t : tail) out.add(t);
  out.own(std::move(end));
}

}  // namespace

namespace detail {

EncodedMap encodeMapPieces(const Map& map, const std::string& source) {
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
  std::vector<std::string_view> key_rows;  // the database's own memory, not copied
  key_rows.reserve(n);
  for (int f = 0; f < db.size(); ++f) key_rows.emplace_back(reinterpret_cast<const char*>(db.global(f)), sizeof(float) * dim);
  const std::optional<IvfState> state = db.ivfState();
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
  // The sessions too: a reader that predates them skips the section and sees one drive.
  std::string sessions;
  if (!map.sessions.empty()) {
    put<uint64_t>(sessions, map.sessions.size());
    for (const MapSession& s : map.sessions) {
      putText(sessions, s.name);
      put<uint64_t>(sessions, static_cast<uint64_t>(s.first));
      put<uint64_t>(sessions, static_cast<uint64_t>(s.frames));
    }
  }
  const bool has_footprints = !footprints.empty(), has_sights = !sights.empty(), has_sessions = !sessions.empty();
  EncodedMap out;
  putSection(out, "CONF", std::move(conf));
  putSection(out, "FRMS", std::move(names));
  if (map.hasPoses()) putSection(out, "POSE", std::move(poses));
  putSection(out, "NODE", std::move(nodes));
  putSection(out, "KEYS", std::move(keys), key_rows);
  if (state) putSection(out, "IVFS", encodeIvf(*state, dim));
  if (has_footprints) putSection(out, "FTPR", std::move(footprints));
  if (has_sights) putSection(out, "SGHT", std::move(sights));
  if (has_sessions) putSection(out, "SESS", std::move(sessions));

  std::string header(kMagic);
  put<uint32_t>(header, kFormatVersion);
  put<uint32_t>(header, 4 + (map.hasPoses() ? 1 : 0) + (state ? 1 : 0) + (has_footprints ? 1 : 0) + (has_sights ? 1 : 0) +
                                (has_sessions ? 1 : 0));
  put<uint64_t>(header, kHeaderBytes + out.size());
  put<uint64_t>(header, fingerprint(map.config));
  put<uint32_t>(header, 0);  // flags: none so far
  put<uint32_t>(header, crc(header));
  out.prepend(std::move(header));
  return out;
}

}  // namespace detail

std::string encodeMap(const Map& map, const std::string& source) {
  const detail::EncodedMap pieces = detail::encodeMapPieces(map, source);
  std::string out;
  out.reserve(pieces.size());
  for (std::string_view piece : pieces.pieces()) out += piece;
  return out;
}


}  // namespace sgtllc::map
