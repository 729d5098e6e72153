#include "sgtllc/map/map.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <unordered_set>

#include <Eigen/LU>

#include "sgtllc/io/config_yaml.h"
#include "sgtllc/retrieval/retrieval_key.h"

namespace sgtllc::map {
namespace {

constexpr double kRigidTolerance = 1e-3;

/// Keys a map depends on (docs/map-format.md, "Configuration"): whole sections (the labeller too: geometric and
/// network labels give other nodes), or single retrieval keys.
bool storedField(std::string_view key) {
  if (key == "labels.format") return false;  // how label files hold the ids, not which ids: the nodes are the same
  // How a query's score counts nodes, not which nodes a map holds.
  constexpr std::string_view kScoreOnly = ".score_unmatched";
  if (key.size() > kScoreOnly.size() && key.substr(key.size() - kScoreOnly.size()) == kScoreOnly) return false;
  for (std::string_view section : {"labels.", "labeller.", "cluster.", "graph.", "descriptor."}) {
    if (key.substr(0, section.size()) == section) return true;
  }
  return key == "retrieval.key" || key == "retrieval.histogram_bins" || key == "retrieval.histogram_range";
}

}  // namespace

ConfigFields mapConfig(const Config& config) {
  ConfigFields fields;
  for (auto& field : io::configValues(config)) {
    if (storedField(field.first)) fields.push_back(std::move(field));
  }
  return fields;
}

uint64_t fingerprint(const ConfigFields& fields) {
  uint64_t h = 14695981039346656037ull;
  const auto mix = [&h](std::string_view text) {
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xffu) * 1099511628211ull;  // a separator no UTF-8 text contains, so ("ab","c") ≠ ("a","bc")
  };
  for (const auto& [key, value] : fields) {
    mix(key);
    mix(value);
  }
  return h;
}

void checkCompatible(const Map& map, const Config& config, const std::string& source) {
  const ConfigFields mine = mapConfig(config);
  const auto incompatible = [&](const std::string& what) {
    throw MapError(MapProblem::kIncompatible,
                   source + ": the map was built with another configuration: " + what +
                       " (these fields decide what a map stores; use the map's configuration, see `sgtllc map info`)");
  };
  for (size_t i = 0; i < std::max(mine.size(), map.config.size()); ++i) {
    if (i >= map.config.size()) incompatible(mine[i].first + " is not in the map");
    if (i >= mine.size()) incompatible(map.config[i].first + " is not in this configuration");
    if (mine[i].first != map.config[i].first) {
      incompatible("the map has " + map.config[i].first + " where the configuration has " + mine[i].first);
    }
    if (mine[i].second != map.config[i].second) {
      incompatible(mine[i].first + ": the map was built with " + map.config[i].second + ", the configuration has " +
                   mine[i].second);
    }
  }
  // Equal fields imply what follows; a file that passed its checksums but breaks it was written wrongly.
  const auto corrupted = [&](const std::string& what) {
    throw MapError(MapProblem::kCorrupted, source + ": corrupted map: " + what);
  };
  const FrameDatabase& db = map.database;
  if (db.size() > 0 && db.globalDimension() != retrieval::retrievalKeySize(config)) {
    corrupted("keys of " + std::to_string(db.globalDimension()) + " entries, the configuration's have " +
              std::to_string(retrieval::retrievalKeySize(config)));
  }
  for (int f = 0; f < db.size(); ++f) {
    const std::vector<Node>& nodes = db.nodes(f);
    if (static_cast<int>(nodes.size()) > config.graph.max_nodes) {
      corrupted("frame " + map.names.at(f) + " has more than graph.max_nodes nodes");
    }
    for (const Node& n : nodes) {
      if (n.label < 0 || n.label >= config.numClasses()) corrupted("frame " + map.names.at(f) + " has a bad label");
    }
  }
}

void checkFrames(const Map& map, const std::string& source) {
  const auto invalid = [&](const std::string& what) { throw MapError(MapProblem::kInvalid, source + ": " + what); };
  const size_t n = static_cast<size_t>(map.size());
  if (map.names.size() != n) {
    invalid(std::to_string(map.names.size()) + " frame names for " + std::to_string(n) + " frames");
  }
  if (!map.poses.empty() && map.poses.size() != n) {
    invalid(std::to_string(map.poses.size()) + " poses for " + std::to_string(n) + " frames (all or none)");
  }
  if (!map.footprints.empty() && map.footprints.size() != n) {
    invalid(std::to_string(map.footprints.size()) + " footprints for " + std::to_string(n) + " frames (all or none)");
  }
  for (size_t f = 0; f < map.footprints.size(); ++f) {
    const Footprint& fp = map.footprints[f];
    // Checked before the grid, which may be empty: the writer writes a sight of any frame that has one.
    const size_t sectors = static_cast<size_t>(kSightSectors), low = fp.sight.low.size(), high = fp.sight.high.size();
    if (!(low == high && (low == 0 || low == sectors))) {
      invalid("the sight of frame '" + map.names[f] + "' has " + std::to_string(low) + " and " + std::to_string(high) +
              " sectors, not none or " + std::to_string(kSightSectors) + " in both layers");
    }
    if (fp.empty()) continue;
    if (fp.dilated || !isMapFootprintGrid(fp.cell, fp.half) || fp.bits.size() != Footprint::words(fp.half)) {
      invalid("the footprint of frame '" + map.names[f] + "' is not a footprint grid (dilated, or its cell, size "
              "or bits do not agree)");
    }
  }
  std::unordered_set<std::string_view> session_names;
  size_t next = 0;
  for (const MapSession& s : map.sessions) {
    if (s.name.empty() || s.name.find('/') != std::string::npos || !session_names.insert(s.name).second) {
      invalid("session name '" + s.name + "' is empty, holds a '/' or is used twice");
    }
    if (s.first < 0 || static_cast<size_t>(s.first) != next || s.frames < 0 ||
        static_cast<size_t>(s.frames) > n - next) {
      invalid("session '" + s.name + "' (frames " + std::to_string(s.first) + " + " + std::to_string(s.frames) +
              ") does not follow the session before it within the " + std::to_string(n) + " frames");
    }
    next += static_cast<size_t>(s.frames);
  }
  if (!map.sessions.empty() && next != n) {
    invalid("the sessions hold " + std::to_string(next) + " of the " + std::to_string(n) + " frames");
  }
  std::unordered_set<std::string_view> seen;
  for (const std::string& name : map.names) {
    if (name.empty()) invalid("a frame has an empty name");
    if (!seen.insert(name).second) invalid("frame name '" + name + "' is used twice (names must be unique)");
  }
  for (size_t f = 0; f < map.poses.size(); ++f) {
    const Eigen::Matrix4d& T = map.poses[f];
    if (!T.allFinite()) invalid("the pose of frame '" + map.names[f] + "' is not finite");
    // The bound the trajectory readers apply (io/trajectory.h): beyond it the matrix is not a rotation at all.
    const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
    const double orthonormal = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    const double det = R.determinant();
    if (orthonormal > kRigidTolerance || std::abs(det - 1.0) > kRigidTolerance) {
      invalid("the pose of frame '" + map.names[f] + "' is not a rigid motion (|RᵀR − I| = " +
              std::to_string(orthonormal) + ", det R = " + std::to_string(det) + "; at most 0.001 off)");
    }
  }
}

Map makeMap(const FrameDatabase& database, const Config& config, std::vector<std::string> names,
            std::vector<Eigen::Matrix4d> poses, std::vector<Footprint> footprints) {
  Map map;
  map.config = mapConfig(config);
  map.names = std::move(names);
  map.poses = std::move(poses);
  // A map of frames that all lack one (node input, the check off) stores no footprint section.
  const bool any = std::any_of(footprints.begin(), footprints.end(), [](const Footprint& f) { return !f.empty(); });
  if (any) map.footprints = std::move(footprints);
  // One copy of the keys at their exact size (adding frame by frame grows the storage by doubling: three times
  // the keys at the last growth, gigabytes for a million frames; BENCHMARKS.md "Retrieval at scale"). A trained
  // inverted file goes into the map as it is, so a loaded map searches as the saved detector did.
  map.database = database.copy();
  map.database.setSearch(config.retrieval, config.threads);
  checkFrames(map, "map");
  return map;
}

}  // namespace sgtllc::map
