// The map file format, version 1 (docs/map-format.md). Every multi-byte value is little-endian; the writer and
// reader copy host words, so a big-endian host is refused at compile time rather than writing other files.
#include "sgtllc/map/map_format.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <set>

#include "map/map_bytes.h"
#include "map/ivf_section.h"

namespace sgtllc::map {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "the map format is little-endian and this code copies host words: port it before using a big-endian host");

namespace {

using namespace detail;  // put, putText, Reader (map_bytes.h), encodeIvf, readIvfState (ivf_section.h)

constexpr std::string_view kMagic("SGTLLMAP", 8);
constexpr size_t kHeaderBytes = 40;       // magic, version, sections, file bytes, fingerprint, flags, checksum
constexpr size_t kSectionHeadBytes = 16;  // tag, section version, payload bytes
constexpr size_t kNodeBytes = 3 * sizeof(double) + sizeof(int32_t);
constexpr uint32_t kSectionVersion = 1;   // of every section this version writes

uint32_t crc(std::string_view bytes) {
  return static_cast<uint32_t>(
      crc32_z(crc32_z(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

void putSection(std::string& out, std::string_view tag, const std::string& payload) {
  const size_t start = out.size();
  out.append(tag.data(), 4);
  put<uint32_t>(out, kSectionVersion);
  put<uint64_t>(out, payload.size());
  out += payload;
  put<uint32_t>(out, crc(std::string_view(out).substr(start)));
}

/// Sections as decoded, before they make a map.
struct Parts {
  std::optional<ConfigFields> config;
  std::optional<std::vector<std::string>> names;
  std::optional<std::vector<Eigen::Matrix4d>> poses;
  std::optional<std::vector<std::vector<Node>>> nodes;
  std::optional<std::pair<uint32_t, std::vector<float>>> keys;  // dimension, row-major keys
  std::optional<IvfState> ivf;                                   // a trained inverted file (retrieval.method ivf)
};

void readConfig(Reader& r, Parts& parts) {
  const uint32_t n = r.get<uint32_t>();
  if (n > r.remaining() / 8) r.fail("a count of " + std::to_string(n) + " fields does not fit in the section");
  ConfigFields fields;
  for (uint32_t i = 0; i < n; ++i) {
    std::string key = r.text();
    fields.emplace_back(std::move(key), r.text());
  }
  parts.config = std::move(fields);
}

void readNames(Reader& r, Parts& parts) {
  std::vector<std::string> names(r.count(sizeof(uint32_t)));
  for (std::string& name : names) name = r.text();
  parts.names = std::move(names);
}

void readPoses(Reader& r, Parts& parts) {
  std::vector<Eigen::Matrix4d> poses(r.count(12 * sizeof(double)), Eigen::Matrix4d::Identity());
  for (Eigen::Matrix4d& T : poses) {
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 4; ++col) T(row, col) = r.get<double>();
    }
  }
  parts.poses = std::move(poses);
}

void readNodes(Reader& r, Parts& parts) {
  std::vector<std::vector<Node>> frames(r.count(sizeof(uint32_t)));
  std::vector<uint32_t> counts(frames.size());
  uint64_t total = 0;
  for (uint32_t& c : counts) total += c = r.get<uint32_t>();
  if (total != r.remaining() / kNodeBytes || r.remaining() % kNodeBytes != 0) {
    r.fail(std::to_string(total) + " nodes declared, " + std::to_string(r.remaining()) + " bytes of them found");
  }
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

struct SectionKind {
  std::string_view tag;
  void (*read)(Reader&, Parts&);
};
constexpr SectionKind kSections[] = {
    {"CONF", readConfig}, {"FRMS", readNames}, {"POSE", readPoses}, {"NODE", readNodes}, {"KEYS", readKeys},
    {"IVFS", readIvf}};

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
  std::string body;
  body.reserve(conf.size() + names.size() + poses.size() + nodes.size() + keys.size() + 5 * 20);
  putSection(body, "CONF", conf);
  putSection(body, "FRMS", names);
  if (map.hasPoses()) putSection(body, "POSE", poses);
  putSection(body, "NODE", nodes);
  putSection(body, "KEYS", keys);
  if (state) putSection(body, "IVFS", ivf);

  std::string out(kMagic);
  put<uint32_t>(out, kFormatVersion);
  put<uint32_t>(out, 4 + (map.hasPoses() ? 1 : 0) + (state ? 1 : 0));
  put<uint64_t>(out, kHeaderBytes + body.size());
  put<uint64_t>(out, fingerprint(map.config));
  put<uint32_t>(out, 0);  // flags: none in version 1
  put<uint32_t>(out, crc(out));
  out.reserve(out.size() + body.size());
  out += body;
  return out;
}

Map decodeMap(std::string_view bytes, const std::string& source, RetrievalMethod method, MapLayout* layout) {
  const auto fail = [&](MapProblem problem, const std::string& what) { throw MapError(problem, source + ": " + what); };
  const std::string sizes = std::to_string(bytes.size()) + " bytes";
  if (bytes.size() < kMagic.size() && kMagic.substr(0, bytes.size()) == bytes) {
    fail(MapProblem::kTruncated, bytes.empty() ? "truncated map file: it is empty" : "truncated map file: " + sizes);
  }
  if (bytes.substr(0, kMagic.size()) != kMagic) fail(MapProblem::kNotAMap, "not an sgtllc map (no SGTLLMAP magic)");
  if (bytes.size() < kHeaderBytes) {
    fail(MapProblem::kTruncated, "truncated map file: " + sizes + ", shorter than the 40-byte header");
  }
  // The 40-byte header keeps its layout in every version, so its checksum is tested first: a damaged version
  // or length reads as damage, not as a newer file.
  Reader head(bytes.substr(0, kHeaderBytes), source + ": corrupted map header: ");
  head.get<uint64_t>();  // magic
  const uint32_t version = head.get<uint32_t>();
  const uint32_t num_sections = head.get<uint32_t>();
  const uint64_t file_bytes = head.get<uint64_t>();
  const uint64_t print = head.get<uint64_t>();
  const uint32_t flags = head.get<uint32_t>();
  const uint32_t header_crc = head.get<uint32_t>();
  if (crc(bytes.substr(0, kHeaderBytes - 4)) != header_crc) fail(MapProblem::kCorrupted, "corrupted map: header checksum mismatch");
  if (version > kFormatVersion) {
    fail(MapProblem::kNewerVersion, "map format version " + std::to_string(version) +
                                        " is newer than this sgtllc reads (" + std::to_string(kFormatVersion) +
                                        "); update sgtllc or rebuild the map");
  }
  if (version == 0 || flags != 0) fail(MapProblem::kCorrupted, "corrupted map: bad version or flags");
  if (bytes.size() < file_bytes) {
    fail(MapProblem::kTruncated, "truncated map file: " + sizes + " of the " + std::to_string(file_bytes) + " it declares");
  }
  if (bytes.size() > file_bytes) {
    fail(MapProblem::kCorrupted, "corrupted map: " + sizes + ", " + std::to_string(bytes.size() - file_bytes) +
                                     " more than the header declares");
  }

  MapLayout seen;
  seen.format_version = version;
  seen.fingerprint = print;
  seen.file_bytes = file_bytes;
  Parts parts;
  std::set<std::string> tags;
  size_t pos = kHeaderBytes;
  for (uint32_t s = 0; s < num_sections; ++s) {
    const std::string at = "corrupted map: section " + std::to_string(s + 1) + " of " + std::to_string(num_sections);
    if (bytes.size() - pos < kSectionHeadBytes + 4) fail(MapProblem::kCorrupted, at + " is cut off");
    Reader sh(bytes.substr(pos, kSectionHeadBytes), source + ": " + at + ": ");
    sh.get<uint32_t>();  // tag
    const uint32_t section_version = sh.get<uint32_t>();
    const uint64_t payload = sh.get<uint64_t>();
    if (payload > bytes.size() - pos - kSectionHeadBytes - 4) fail(MapProblem::kCorrupted, at + " overruns the file");
    const size_t whole = kSectionHeadBytes + static_cast<size_t>(payload);
    uint32_t stored_crc;
    std::memcpy(&stored_crc, bytes.data() + pos + whole, 4);
    if (crc(bytes.substr(pos, whole)) != stored_crc) fail(MapProblem::kCorrupted, at + ": checksum mismatch");
    const std::string tag(bytes.substr(pos, 4));
    const SectionKind* kind = nullptr;
    for (const SectionKind& k : kSections) kind = k.tag == tag ? &k : kind;
    if (kind && section_version > kSectionVersion) {
      fail(MapProblem::kNewerVersion, "map section " + tag + " has version " + std::to_string(section_version) +
                                          ", newer than this sgtllc reads (" + std::to_string(kSectionVersion) + ")");
    }
    if (!tags.insert(tag).second) fail(MapProblem::kCorrupted, at + ": a second " + tag + " section");
    if (kind) {
      Reader r(bytes.substr(pos + kSectionHeadBytes, static_cast<size_t>(payload)),
               source + ": corrupted map: section " + tag + ": ");
      kind->read(r, parts);
      r.end();
    }
    seen.sections.push_back(SectionInfo{tag, section_version, whole + 4, kind != nullptr});
    pos += whole + 4;
  }
  if (pos != bytes.size()) fail(MapProblem::kCorrupted, "corrupted map: bytes after the last section");
  if (!parts.config || !parts.names || !parts.nodes || !parts.keys) {
    fail(MapProblem::kCorrupted, "corrupted map: a section is missing (CONF, FRMS, NODE and KEYS are required)");
  }
  if (fingerprint(*parts.config) != print) fail(MapProblem::kCorrupted, "corrupted map: configuration fingerprint mismatch");
  const size_t n = parts.names->size();
  const auto& [dim, keys] = *parts.keys;
  if (parts.nodes->size() != n || keys.size() / dim != n || (parts.poses && parts.poses->size() != n)) {
    fail(MapProblem::kCorrupted, "corrupted map: the sections disagree on the frame count");
  }

  Map map;
  map.config = std::move(*parts.config);
  map.names = std::move(*parts.names);
  if (parts.poses) map.poses = std::move(*parts.poses);
  RetrievalConfig search;
  search.method = parts.ivf ? RetrievalMethod::kIvf : method;
  map.database = FrameDatabase(search);
  for (size_t f = 0; f < n; ++f) {
    map.database.add(StoredFrame{std::move((*parts.nodes)[f]),
                                 std::vector<float>(keys.begin() + f * dim, keys.begin() + (f + 1) * dim)});
  }
  try {
    if (parts.ivf) {
      if (parts.ivf->centroids.size() != static_cast<size_t>(parts.ivf->lists) * dim) {
        fail(MapProblem::kCorrupted, "corrupted map: the inverted file's centroids are not as long as the keys");
      }
      map.database.restoreIvf(std::move(*parts.ivf));
      search.method = method;
      map.database.setSearch(search);  // the state stays when method is ivf; it is dropped otherwise
    }
  } catch (const std::invalid_argument& e) {
    fail(MapProblem::kCorrupted, std::string("corrupted map: ") + e.what());
  }
  try {
    checkFrames(map, source);
  } catch (const MapError& e) {
    const std::string what = e.what();  // "SOURCE: problem"
    fail(MapProblem::kCorrupted, "corrupted map: " + what.substr(std::min(what.size(), source.size() + 2)));
  }
  if (layout) *layout = std::move(seen);
  return map;
}

}  // namespace sgtllc::map
