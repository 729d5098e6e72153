// Reading the map file format (docs/map-format.md, "Reading"): the header first, then one section at a time, each
// parsed from a small buffer while its crc32 is computed. Nothing is allocated beyond what a count that fits in
// its section's declared bytes (and so in the file) needs, and the bytes themselves are never held whole.
#include "map_decode.h"

#include <algorithm>
#include <cstring>
#include <set>

#include "map_sections.h"
#include "sgtllc/io/input_file.h"

namespace sgtllc::map {
namespace detail {
Map decodeMapFrom(ByteSource& src, const std::string& source, RetrievalMethod method, MapLayout* layout,
                  uint64_t loadable_bytes) {
  const auto fail = [&](MapProblem problem, const std::string& what) { throw MapError(problem, source + ": " + what); };
  const uint64_t size = src.size();
  const std::string sizes = std::to_string(size) + " bytes";
  char head_bytes[kHeaderBytes];
  const size_t head_size = static_cast<size_t>(std::min<uint64_t>(size, kHeaderBytes));
  if (src.read(head_bytes, head_size) != head_size) fail(MapProblem::kTruncated, "truncated map file: it shrank while read");
  const std::string_view bytes(head_bytes, head_size);
  if (size < kMagic.size() && kMagic.substr(0, bytes.size()) == bytes) {
    fail(MapProblem::kTruncated, size == 0 ? "truncated map file: it is empty" : "truncated map file: " + sizes);
  }
  if (bytes.substr(0, kMagic.size()) != kMagic) fail(MapProblem::kNotAMap, "not an sgtllc map (no SGTLLMAP magic)");
  if (size < kHeaderBytes) {
    fail(MapProblem::kTruncated, "truncated map file: " + sizes + ", shorter than the 40-byte header");
  }
  // The 40-byte header keeps its layout in every version, so its checksum is tested first: a damaged version
  // or length reads as damage, not as another version.
  MemorySource head_source(bytes);
  Reader head(head_source, kHeaderBytes, source + ": corrupted map header: ");
  head.get<uint64_t>();  // magic
  const uint32_t version = head.get<uint32_t>();
  const uint32_t num_sections = head.get<uint32_t>();
  const uint64_t file_bytes = head.get<uint64_t>();
  const uint64_t print = head.get<uint64_t>();
  const uint32_t flags = head.get<uint32_t>();
  const uint32_t header_crc = head.get<uint32_t>();
  if (crc32Of(bytes.substr(0, kHeaderBytes - 4)) != header_crc) {
    fail(MapProblem::kCorrupted, "corrupted map: header checksum mismatch");
  }
  if (version > kFormatVersion) {
    fail(MapProblem::kNewerVersion, "map format version " + std::to_string(version) +
                                        " is newer than this sgtllc reads (" + std::to_string(kFormatVersion) +
                                        "); update sgtllc or rebuild the map");
  }
  if (version == 0 || flags != 0) fail(MapProblem::kCorrupted, "corrupted map: bad version or flags");
  if (version < kFormatVersion) {
    fail(MapProblem::kOlderVersion, "written by an older version of the map format (" + std::to_string(version) +
                                        "; this build reads " + std::to_string(kFormatVersion) +
                                        "): rebuild it with `sgtllc run --save-map`");
  }
  if (size < file_bytes) {
    fail(MapProblem::kTruncated, "truncated map file: " + sizes + " of the " + std::to_string(file_bytes) + " it declares");
  }
  if (size > file_bytes) {
    fail(MapProblem::kCorrupted, "corrupted map: " + sizes + ", " + std::to_string(size - file_bytes) +
                                     " more than the header declares");
  }
  // The decoded map takes about 1.1 times its file (docs/map-format.md, "Reading"): refuse what cannot fit
  // rather than fail half way with an allocation error.
  if (file_bytes + file_bytes / 10 > loadable_bytes) {
    fail(MapProblem::kTooLarge, "a map of " + sizes + " (" + io::gibText(file_bytes) +
                                    ") is more than this machine can load (" + io::gibText(loadable_bytes) + " of memory)");
  }

  MapLayout seen;
  seen.format_version = version;
  seen.fingerprint = print;
  seen.file_bytes = file_bytes;
  Parts parts;
  std::set<std::string> tags;
  uint64_t pos = kHeaderBytes;
  for (uint32_t s = 0; s < num_sections; ++s) {
    const std::string at = "corrupted map: section " + std::to_string(s + 1) + " of " + std::to_string(num_sections);
    if (size - pos < kSectionHeadBytes + 4) fail(MapProblem::kCorrupted, at + " is cut off");
    char sh_bytes[kSectionHeadBytes];
    if (src.read(sh_bytes, kSectionHeadBytes) != kSectionHeadBytes) fail(MapProblem::kCorrupted, at + " is cut off");
    const std::string_view section_head(sh_bytes, kSectionHeadBytes);
    MemorySource sh_source(section_head);
    Reader sh(sh_source, kSectionHeadBytes, source + ": " + at + ": ");
    sh.get<uint32_t>();  // tag
    const uint32_t section_version = sh.get<uint32_t>();
    const uint64_t payload = sh.get<uint64_t>();
    if (payload > size - pos - kSectionHeadBytes - 4) fail(MapProblem::kCorrupted, at + " overruns the file");
    const std::string tag(section_head.substr(0, 4));
    Reader r(src, payload, source + ": corrupted map: section " + tag + ": ", crc32Of(section_head));
    // The checksum covers the head too: a section is judged by it before anything else it says is reported.
    const auto checkCrc = [&] {
      const uint32_t computed = r.drain();
      uint32_t stored = 0;
      if (src.read(reinterpret_cast<char*>(&stored), 4) != 4) fail(MapProblem::kCorrupted, at + " is cut off");
      if (computed != stored) fail(MapProblem::kCorrupted, at + ": checksum mismatch");
    };
    const SectionKind* kind = findSection(tag);
    if (kind && section_version > kSectionVersion) {
      checkCrc();
      fail(MapProblem::kNewerVersion, "map section " + tag + " has version " + std::to_string(section_version) +
                                          ", newer than this sgtllc reads (" + std::to_string(kSectionVersion) + ")");
    }
    if (!tags.insert(tag).second) {
      checkCrc();
      fail(MapProblem::kCorrupted, at + ": a second " + tag + " section");
    }
    if (kind) {
      try {
        kind->read(r, parts);
        r.end();
      } catch (const MapError&) {
        checkCrc();  // a damaged section says "checksum mismatch" whatever its damage made the parser see
        throw;
      }
    }
    checkCrc();
    seen.sections.push_back(SectionInfo{tag, section_version, kSectionHeadBytes + payload + 4, kind != nullptr});
    pos += kSectionHeadBytes + payload + 4;
  }
  if (pos != size) fail(MapProblem::kCorrupted, "corrupted map: bytes after the last section");
  if (!parts.config || !parts.names || !parts.nodes || !parts.keys) {
    fail(MapProblem::kCorrupted, "corrupted map: a section is missing (CONF, FRMS, NODE and KEYS are required)");
  }
  if (fingerprint(*parts.config) != print) fail(MapProblem::kCorrupted, "corrupted map: configuration fingerprint mismatch");
  const size_t n = parts.names->size();
  auto& [dim, keys] = *parts.keys;
  if (parts.nodes->size() != n || keys.size() / dim != n || (parts.poses && parts.poses->size() != n) ||
      (parts.footprints && parts.footprints->size() != n) || (parts.sights && parts.sights->size() != n)) {
    fail(MapProblem::kCorrupted, "corrupted map: the sections disagree on the frame count");
  }

  Map map;
  map.config = std::move(*parts.config);
  map.names = std::move(*parts.names);
  if (parts.poses) map.poses = std::move(*parts.poses);
  if (parts.sessions) map.sessions = std::move(*parts.sessions);
  if (parts.sights && !parts.footprints) fail(MapProblem::kCorrupted, "corrupted map: sights (SGHT) without footprints");
  if (parts.footprints) map.footprints = std::move(*parts.footprints);
  if (parts.sights) {
    for (size_t f = 0; f < n; ++f) map.footprints[f].sight = std::move((*parts.sights)[f]);
  }
  RetrievalConfig search;
  search.method = parts.ivf ? RetrievalMethod::kIvf : method;
  map.database = FrameDatabase(search);
  try {
    map.database.assign(std::move(*parts.nodes), std::move(keys));  // the keys are moved, not copied
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

}  // namespace detail

Map decodeMap(std::string_view bytes, const std::string& source, RetrievalMethod method, MapLayout* layout) {
  detail::MemorySource memory(bytes);
  return detail::decodeMapFrom(memory, source, method, layout, UINT64_MAX);  // the bytes are in memory already
}

}  // namespace sgtllc::map
