// Shared pieces of the sgtllc subcommands: input loading, output guards, formatting, progress.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "sgtllc/config.h"
#include "sgtllc/detector.h"
#include "sgtllc/types.h"

namespace sgtllc::cli {

/// JSON objects keep their keys in insertion order, so output reads in a fixed, sensible order.
using Json = nlohmann::ordered_json;

/// Exit codes: 0 success, 1 bad input or failure, 2 bad command line (CLI11).
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

/// Configuration from --config (or the defaults), with --threads applied if given (> 0).
Config loadConfigOption(const std::string& path, int threads);

/// A scan from a KITTI .bin (labels from @p label_path or the SemanticKITTI default) or a PCD with a label field.
LabeledCloud loadScan(const std::string& path, const std::string& label_path, const std::string& label_field);

/// Refuses to overwrite an existing file unless @p force: nothing a user gave us is overwritten by accident.
void checkWritable(const std::string& path, bool force);

/// Writes @p text to @p path via a temporary file and a rename, so a failure never leaves half a file.
void writeFileAtomically(const std::string& path, const std::string& text);

/// Warnings about dropped points (non-finite coordinates, unknown ids, no nodes) on stderr.
void warnAboutInput(const std::string& name, const ExtractionStats& stats, int num_nodes);

Json matrixJson(const Eigen::Matrix4d& T);
std::string matrixText(const Eigen::Matrix4d& T, const std::string& indent);
Json timingJson(const StageTimes& t, double load_ms);

/// "%.*f" formatting.
std::string fixed(double v, int digits);

/// A one-line progress bar on stderr, drawn only when stderr is a terminal, at most ten times a second.
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
  std::chrono::steady_clock::time_point last_;
};

}  // namespace sgtllc::cli
