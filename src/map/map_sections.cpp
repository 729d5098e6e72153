#include "map_sections.h"

#include <cmath>
#include <cstdint>
#include <string>

#include "ivf_section.h"

namespace sgtllc::map::detail {
namespace {

constexpr size_t kNodeBytes = 3 * sizeof(double) + sizeof(int32_t);

void readConfig(Reader& r, Parts& parts) {
  const uint32_t n = r.get<uint32_t>();
  if (n > r.remaining() / 8) r.fail("a count of " + std::to_string(n) + " fields does not fit in the section");
  ConfigFields fields;  // grown as fields parse: a damaged count must not allocate before the checksum is seen
  for (uint32_t i = 0; i < n; ++i) {
    std::string key = r.text();
    fields.emplace_back(std::move(key), r.text());
  }
  parts.config = std::move(fields);
}

void readNames(Reader& r, Parts& parts) {
  const size_t n = r.count(sizeof(uint32_t));
  std::vector<std::string> names;  // grown as names parse (32 bytes a string against 4 bytes of file)
  for (size_t i = 0; i < n; ++i) names.push_back(r.text());
  parts.names = std::move(names);
}

void readPoses(Reader& r, Parts& parts) {
  std::vector<Eigen::Matrix4d> poses(r.count(12 * sizeof(double)), Eigen::Matrix4d::Identity());
  for (Eigen::Matrix4d& T : poses) {
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 4; ++col) T(row, col) = r.get<double>();
    }
  }
  parts.poses = std::move(poses);  // checkFrames() tests that they are finite rigid motions
}

void readNodes(Reader& r, Parts& parts) {
  // The counts first (4 bytes each, as in the file), then the frames once the counts match the bytes left.
  std::vector<uint32_t> counts(r.count(sizeof(uint32_t)));
  uint64_t total = 0;
  for (uint32_t& c : counts) total += c = r.get<uint32_t>();
  if (total != r.remaining() / kNodeBytes || r.remaining() % kNodeBytes != 0) {
    r.fail(std::to_string(total) + " nodes declared, " + std::to_string(r.remaining()) + " bytes of them found");
  }
  std::vector<std::vector<Node>> frames(counts.size());
  for (size_t f = 0; f < frames.size(); ++f) {
    frames[f].resize(counts[f]);
    for (Node& n : frames[f]) {
      for (int k = 0; k < 3; ++k) n.centre[k] = r.get<double>();
      n.label = r.get<int32_t>();
      if (!n.centre.allFinite()) r.fail("a node centre is not finite");
      if (n.label < 0 || n.label >= kMaxClasses) r.fail("a node label is out of range");
    }
  }
  parts.nodes = std::move(frames);
}

void readKeys(Reader& r, Parts& parts) {
  const uint32_t dim = r.get<uint32_t>();
  const uint64_t n = r.get<uint64_t>();
  if (dim == 0 || dim > (1u << 20)) r.fail("a key length of " + std::to_string(dim));
  if (n != r.remaining() / (sizeof(float) * dim) || r.remaining() % (sizeof(float) * dim) != 0) {
    r.fail(std::to_string(n) + " keys declared, " + std::to_string(r.remaining()) + " bytes of them found");
  }
  std::vector<float> keys(static_cast<size_t>(n) * dim);
  for (float& v : keys) {
    v = r.get<float>();
    if (!std::isfinite(v)) r.fail("a key entry is not finite");
  }
  parts.keys.emplace(dim, std::move(keys));
}

void readIvf(Reader& r, Parts& parts) { parts.ivf = readIvfState(r); }

void readFootprints(Reader& r, Parts& parts) {
  // Each frame takes at least its cell and half (8 bytes); a grid's words are counted against the bytes left.
  const size_t n = r.count(sizeof(float) + sizeof(int32_t));
  std::vector<Footprint> frames;  // grown as frames parse: a damaged count must not allocate before the checksum
  for (size_t f = 0; f < n; ++f) {
    Footprint fp;
    const float cell = r.get<float>();
    const int32_t half = r.get<int32_t>();
    if (half != 0) {
      if (!isMapFootprintGrid(cell, half)) r.fail("a footprint grid of " + std::to_string(half) + " half-cells");
      const uint64_t words = Footprint::words(half);
      if (words > r.remaining() / sizeof(uint64_t)) r.fail("a footprint does not fit in the section");
      fp.cell = cell;
      fp.half = half;
      fp.bits.resize(words);
      for (uint64_t& w : fp.bits) w = r.get<uint64_t>();
    } else if (cell != 0.0f) {
      r.fail("an empty footprint with a cell size");
    }
    frames.push_back(std::move(fp));
  }
  parts.footprints = std::move(frames);
}

void readSights(Reader& r, Parts& parts) {
  // Each frame takes at least its sector count (2 bytes); its sectors are counted against the bytes left.
  const size_t n = r.count(sizeof(uint16_t));
  std::vector<Sight> frames;  // grown as frames parse, as the footprints
  for (size_t f = 0; f < n; ++f) {
    Sight sight;
    const uint16_t sectors = r.get<uint16_t>();
    if (sectors != 0 && sectors != kSightSectors) r.fail("a sight of " + std::to_string(sectors) + " sectors");
    if (sectors > r.remaining() / 2) r.fail("a sight does not fit in the section");
    for (std::vector<uint8_t>* layer : {&sight.low, &sight.high}) {
      layer->resize(sectors);
      for (uint8_t& v : *layer) v = r.get<uint8_t>();
    }
    frames.push_back(std::move(sight));
  }
  parts.sights = std::move(frames);
}

void readSessions(Reader& r, Parts& parts) {
  // Each session takes at least its name's length and two counts (20 bytes); checkFrames() tests the tiling.
  const size_t n = r.count(sizeof(uint32_t) + 2 * sizeof(uint64_t));
  std::vector<MapSession> sessions;  // grown as sessions parse, as the names
  for (size_t s = 0; s < n; ++s) {
    MapSession session;
    session.name = r.text();
    const uint64_t first = r.get<uint64_t>(), frames = r.get<uint64_t>();
    if (first > INT32_MAX || frames > INT32_MAX) r.fail("a session's frames are out of range");
    session.first = static_cast<int>(first);
    session.frames = static_cast<int>(frames);
    sessions.push_back(std::move(session));
  }
  parts.sessions = std::move(sessions);
}

constexpr SectionKind kSections[] = {
    {"CONF", readConfig}, {"FRMS", readNames}, {"POSE", readPoses}, {"NODE", readNodes}, {"KEYS", readKeys},
    {"IVFS", readIvf}, {"FTPR", readFootprints}, {"SGHT", readSights},
    {"SESS", readSessions}};

}  // namespace

const SectionKind* findSection(std::string_view tag) {
  for (const SectionKind& k : kSections) {
    if (k.tag == tag) return &k;
  }
  return nullptr;
}

}  // namespace sgtllc::map::detail
