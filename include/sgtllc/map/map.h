/// @file map.h
/// @brief A saved loop database: the frames a detector stored, their names and (optionally) poses, and the
///        configuration fields their contents depend on (docs/map-format.md).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sgtllc/config.h"
#include "sgtllc/database.h"
#include "sgtllc/footprint.h"
#include "sgtllc/types.h"

namespace sgtllc::map {

/// Configuration fields as (YAML key, printed value) pairs, in print order.
using ConfigFields = std::vector<std::pair<std::string, std::string>>;

/// One drive a map holds (docs/sessions.md): frames first … first + frames − 1 (none when every frame of a drive
/// was already covered by the map).
struct MapSession {
  std::string name;  ///< non-empty, unique in the map, without '/'
  int first = 0;
  int frames = 0;
};

/// A map: what a LoopDetector stored for each frame (nodes and retrieval key, in FrameDatabase), the frame names,
/// optional poses, and the configuration fields those depend on.
struct Map {
  ConfigFields config;                ///< mapConfig() of the configuration the map was built with
  std::vector<std::string> names;     ///< one per frame, non-empty and unique (the sequence's file stems)
  /// T_world_frame (the sensor/LiDAR frame in the map's world frame), one per frame, or none at all.
  std::vector<Eigen::Matrix4d> poses;
  FrameDatabase database;             ///< frame i of the map is database frame i
  /// The frames' footprints (algorithm §7.7; not dilated), one per frame (an empty one where a frame had none:
  /// node input), or none at all: a relocalization then runs without the footprint check and the consistency path.
  std::vector<Footprint> footprints;
  /// The drives merged into the map (SessionPipeline), in frame order, together covering every frame once; or
  /// none: one drive, unnamed (a map saved by `run --save-map`).
  std::vector<MapSession> sessions;

  int size() const { return database.size(); }
  bool hasPoses() const { return !poses.empty(); }
};

/// Largest Footprint::half a map accepts: a grid of 2·4096 cells a side (8 MB), far above the 80 of the defaults.
constexpr int kMaxFootprintHalf = 4096;

/// Whether a footprint of cell side @p cell and @p half half-cells is a grid a map may hold (checked on reading
/// and before writing): a finite positive cell, 1 ≤ half ≤ kMaxFootprintHalf.
inline bool isMapFootprintGrid(float cell, int half) {
  return cell > 0.0f && cell <= std::numeric_limits<float>::max() && half > 0 && half <= kMaxFootprintHalf;
}

/// What went wrong with a map, so callers (and tests) can tell the cases apart; the message says it in words.
enum class MapProblem {
  kNotAMap,       ///< the bytes do not start with the map magic
  kTruncated,     ///< fewer bytes than the header declares
  kCorrupted,     ///< a checksum, a length or a value is wrong
  kNewerVersion,  ///< written by a newer sgtllc (format or section version above what this one reads)
  kOlderVersion,  ///< written by an older sgtllc in a format version this one no longer reads: rebuild the map
  kTooLarge,      ///< the header declares more bytes than this machine can load (its memory, or ulimit -v)
  kIncompatible,  ///< built with a configuration whose stored contents differ from this one's (mapConfig)
  kInvalid,       ///< a map that cannot be saved (names missing or repeated, poses for some frames only, …)
};

/// Error of reading, checking or writing a map; the message names the map's source (file) and the problem.
class MapError : public Error {
 public:
  MapError(MapProblem problem, const std::string& message) : Error(message), problem_(problem) {}
  MapProblem problem() const { return problem_; }

 private:
  MapProblem problem_;
};

/// The fields of @p config that change what a map stores or how stored frames compare (docs/map-format.md): the
/// class set and label mapping (labels.*), node extraction (cluster.*), the graph (graph.*), the local and global
/// descriptors (descriptor.*) and the retrieval key (retrieval.key, histogram_bins, histogram_range). Query-time
/// settings (candidates, exclusion, thresholds of association and verification, registration, threads) are not
/// among them: a map may be searched with other values.
ConfigFields mapConfig(const Config& config);

/// 64-bit FNV-1a of the fields' text: the fingerprint a map file's header carries.
uint64_t fingerprint(const ConfigFields& fields);

/// Throws MapError(kIncompatible) naming @p source and the first differing field ("retrieval.histogram_bins: the
/// map was built with 10, the configuration has 12") unless @p map was built with fields equal to
/// mapConfig(@p config); then checks that every stored frame fits @p config (key length, node labels below the
/// class count, at most graph.max_nodes nodes), else MapError(kCorrupted).
void checkCompatible(const Map& map, const Config& config, const std::string& source);

/// A map of the frames in @p database (copied), built with @p config, named @p names (one per frame) and, if
/// @p poses is not empty, placed by them (one per frame), with @p footprints if not empty (one per frame:
/// LoopDetector::footprints). Throws MapError(kInvalid) if the counts differ, a name is empty or repeated, or a
/// footprint is dilated or does not fill its grid.
Map makeMap(const FrameDatabase& database, const Config& config, std::vector<std::string> names,
            std::vector<Eigen::Matrix4d> poses = {}, std::vector<Footprint> footprints = {});

/// Throws MapError(kInvalid) naming @p source unless names and poses fit the database (counts; names non-empty and
/// unique; poses finite rigid motions: |RᵀR − I| and |det R − 1| at most 1e-3, the trajectory readers' bound) and
/// the sessions, if any, cover the frames in order, each with a unique name without '/'.
void checkFrames(const Map& map, const std::string& source);

}  // namespace sgtllc::map
