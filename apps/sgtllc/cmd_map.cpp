// `sgtllc map info MAP`: what a map file holds (docs/map-format.md).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "common.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/map/map_file.h"

namespace sgtllc::cli {
namespace {

std::string hex(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

void mapInfo(const std::string& path, bool json) {
  map::MapLayout layout;
  const map::Map m = map::readMapFile(path, &layout);
  size_t nodes = 0;
  for (int f = 0; f < m.size(); ++f) nodes += m.database.nodes(f).size();
  const double per_frame = m.size() ? static_cast<double>(layout.file_bytes) / m.size() : 0.0;
  const auto footprints = std::count_if(m.footprints.begin(), m.footprints.end(),
                                        [](const Footprint& f) { return !f.empty(); });
  if (json) {
    Json sections = Json::array();
    for (const map::SectionInfo& s : layout.sections) {
      sections.push_back({{"tag", s.tag}, {"version", s.version}, {"bytes", s.bytes}, {"known", s.known}});
    }
    Json config = Json::object();
    for (const auto& [key, value] : m.config) config[key] = value;
    Json sessions = Json::array();
    for (const map::MapSession& s : m.sessions) {
      sessions.push_back({{"name", s.name}, {"first_frame", s.first}, {"frames", s.frames}});
    }
    std::cout << jsonText({{"map", path},
                           {"format_version", layout.format_version},
                           {"bytes", layout.file_bytes},
                           {"frames", m.size()},
                           {"poses", m.hasPoses()},
                           {"footprints", footprints},
                           {"sessions", sessions},
                           {"nodes", nodes},
                           {"key_length", m.size() ? m.database.globalDimension() : 0},
                           {"bytes_per_frame", per_frame},
                           {"config_fingerprint", hex(layout.fingerprint)},
                           {"sections", sections},
                           {"config", config}})
              << "\n";
    return;
  }
  // Frame names, section tags and configuration text are the file's bytes: escaped before they reach the terminal.
  using io::escapeContent;
  std::cout << "map " << path << ": format version " << layout.format_version << ", " << layout.file_bytes
            << " bytes\n"
            << "frames " << m.size() << " (" << (m.hasPoses() ? "with poses" : "no poses") << ")";
  if (m.size() > 0) {
    std::cout << ", first " << escapeContent(m.names.front(), io::kNameBytes) << ", last "
              << escapeContent(m.names.back(), io::kNameBytes) << "\n"
              << "nodes " << nodes << " (" << fixed(static_cast<double>(nodes) / m.size(), 1) << " per frame), key "
              << m.database.globalDimension() << " floats, " << fixed(per_frame, 0) << " bytes per frame";
    // Relocalization checks a candidate's structure only where its frame kept a footprint (algorithm §7.7).
    std::cout << "\nfootprints " << footprints << " of " << m.size() << " frames";
  }
  if (!m.sessions.empty()) {
    // Merged drives (docs/sessions.md), in frame order.
    std::cout << "\nsessions " << m.sessions.size() << ":";
    for (const map::MapSession& s : m.sessions) {
      std::cout << "\n  " << escapeContent(s.name, io::kNameBytes) << ": " << s.frames << " frames";
      // A drive the map already held everywhere adds no frame (docs/sessions.md, thinning): no range to name.
      if (s.frames == 0) continue;
      std::cout << " (" << escapeContent(m.names.at(static_cast<size_t>(s.first)), io::kNameBytes) << " .. "
                << escapeContent(m.names.at(static_cast<size_t>(s.first + s.frames - 1)), io::kNameBytes) << ")";
    }
  }
  std::cout << "\nconfiguration fingerprint " << hex(layout.fingerprint) << "\nsections:\n";
  for (const map::SectionInfo& s : layout.sections) {
    std::cout << "  " << escapeContent(s.tag) << " v" << s.version << "  " << s.bytes << " bytes"
              << (s.known ? "" : "  (not known to this version: skipped)") << "\n";
  }
  std::cout << "configuration (these must equal a localize or resume configuration's):\n";
  for (const auto& [key, value] : m.config) {
    std::cout << "  " << escapeContent(key) << ": " << escapeContent(value, 1024) << "\n";
  }
}

}  // namespace

void addMapCommand(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("map", "Inspect map files (`sgtllc run --save-map`)");
  cmd->require_subcommand(1);
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  CLI::App* info = cmd->add_subcommand("info", "Print what a map holds: version, frames, poses, sessions, configuration, sections");
  info->add_option("MAP", *path, "map file")->required();
  info->add_flag("--json", *json, "print it as one JSON object");
  info->callback([path, json] { mapInfo(*path, *json); });
}

}  // namespace sgtllc::cli
