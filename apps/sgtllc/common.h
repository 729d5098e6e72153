// Shared pieces of the sgtllc subcommands: input loading, output guards, formatting, progress.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/pipeline/frame_source.h"
#include "sgtllc/types.h"

namespace sgtllc::cli {

/// JSON objects keep their keys in insertion order, so output reads in a fixed, sensible order.
using Json = nlohmann::ordered_json;

/// Exit codes: 0 success, 1 bad input or failure, 2 bad command line (CLI11).
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

/// The command line this process was started with (set by main), for reports.
std::string& commandLine();

/// Configuration from --config (or the defaults), with --threads applied if given (> 0) to the detector's
/// `threads` and the back end's `backend.solver.num_threads`, and --labeller (file | geometric; "" = the
/// config's labeller.source).
Config loadConfigOption(const std::string& path, int threads, const std::string& labeller = "");

/// The frames of a sequence: the node files in @p nodes if given (--nodes), else @p sequence's scans and labels
/// (from @p labels_dir if given: --labels-dir; none with labeller.source geometric).
pipeline::FrameSource frameSource(const std::string& sequence, const std::string& nodes, const Config& config,
                              const std::string& labels_dir = "");

/// What a SEQ_DIR argument holds (run, eval, localize; io/sequence.h).
inline constexpr const char* kSequenceFolderHelp =
    "sequence folder: velodyne/*.bin (SemanticKITTI), or .bin, .pcd or .ply scans (one format) in the folder itself, "
    "frames in name order; labels from labels/NAME.label, or a PCD/PLY 'label' field, or --labels-dir, or none with "
    "--labeller geometric";

/// Adds `--labeller file|geometric` to @p cmd.
void addLabellerOption(CLI::App* cmd, std::string* labeller);

/// One input frame reduced to graph nodes.
struct FrameNodes {
  std::vector<Node> nodes;
  bool from_node_file = false;  ///< read from a node file instead of extracted from points
  size_t points = 0;            ///< points of the scan (0 for a node file)
  /// The scan, kept for the fine registration when registration.pair is on (empty for a node file)
  LabeledCloud cloud;
  Footprint footprint;          ///< the scan's footprint (empty for a node file), from the extraction's pass
  ExtractionStats stats;        ///< point bookkeeping (a node file's unknown ids count as unknown_label_points)
  double load_ms = 0.0;
  double extraction_ms = 0.0;
};

/// Nodes of a KITTI .bin scan (labels from @p label_path or the SemanticKITTI default), a PCD or PLY scan with a
/// label field (or with @p label_path: a .label file), or a node file (.txt: one `x y z label` row per node, label
/// a raw id mapped by config.labels). With the geometric labeller, a .bin, PCD or PLY without labels
/// (io::readScanPoints).
FrameNodes loadFrameNodes(const std::string& path, const std::string& label_path, const std::string& label_field,
                          const Config& config);

/// Refuses an output file that exists (unless @p force), is a folder, or whose folder is missing or not
/// writable: io::checkOutputFile with the CLI's --force. Called for every output before any work.
void checkWritable(const std::string& path, bool force);

/// A report folder may be written if it does not exist yet, or (unless @p force) holds none of @p files.
/// Throws sgtllc::Error naming the first file that exists, or the folder if it is not one.
void checkReportFiles(const std::string& dir, const std::vector<std::string>& files, bool force);

/// io::writeFileAtomically with the CLI's --force: a file that appeared since checkWritable() is kept.
void writeOutput(const std::string& path, const std::string& text, bool force);

/// Warnings about dropped points (non-finite coordinates, unknown ids, no nodes) on stderr; @p unit names what
/// carried the unknown ids ("points", or "node rows" for a node file).
void warnAboutInput(const std::string& name, const ExtractionStats& stats, int num_nodes,
                    const char* unit = "points");

/// Points with label ids outside the configured label set, summed over a run: one warning at the end instead of
/// one line per frame.
class UnknownLabels {
 public:
  void add(const std::string& frame, size_t points);
  /// "warning: ignored N points in F of T frames (first: NAME) whose label id ..." on stderr, if any.
  void warn() const;

 private:
  size_t points_ = 0, frames_ = 0, seen_ = 0;
  std::string first_;
};

Json matrixJson(const Eigen::Matrix4d& T);
std::string matrixText(const Eigen::Matrix4d& T, const std::string& indent);
/// Indented JSON text; bytes that are not UTF-8 (from file names) are replaced, never an error.
std::string jsonText(const Json& j);
Json timingJson(const StageTimes& t, double load_ms);

/// "%.*f" formatting.
std::string fixed(double v, int digits);

/// A one-line progress bar on stderr, drawn only when stderr is a terminal, at most ten times a second, with the
/// rate (frames/s) and the time left at that rate. Never part of an output file or of stdout.
class Progress {
 public:
  Progress(std::string what, size_t total);
  void update(size_t done, const std::string& extra);
  /// Clears the bar line so other output can be printed.
  void clear();
  void finish();

 private:
  std::string what_;
  size_t total_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_;
};

/// "m:ss" (or "h:mm:ss") of @p seconds, rounded down; "?" if not finite or negative.
std::string clockText(double seconds);

}  // namespace sgtllc::cli
