#include "common.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <utility>

#include "sgtllc/graph.h"
#include "sgtllc/io/config_yaml.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/io/scan_file.h"
#include "sgtllc/label/cloud_labeller.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {

std::string& commandLine() {
  static std::string line;
  return line;
}

Config loadConfigOption(const std::string& path, int threads, const std::string& labeller) {
  Config config = path.empty() ? Config{} : io::loadConfig(path);
  if (labeller == "geometric") {
    config.labeller.source = LabelSource::kGeometric;
  } else if (labeller == "hybrid") {
    config.labeller.source = LabelSource::kHybrid;
  } else if (labeller == "file") {
    config.labeller.source = LabelSource::kFile;
  } else if (!labeller.empty()) {
    throw Error("--labeller " + labeller + ": expected file, geometric or hybrid");
  }
  if (threads > 0) {
    config.threads = threads;
    config.backend.solver.num_threads = threads;
  }
  config.validate();
  return config;
}

pipeline::FrameSource frameSource(const std::string& sequence, const std::string& nodes, const Config& config,
                              const std::string& labels_dir) {
  if (!labels_dir.empty() && !nodes.empty()) throw Error("--labels-dir and --nodes exclude each other");
  if (!labels_dir.empty() && config.labeller.source == LabelSource::kGeometric) {
    throw Error("--labels-dir and --labeller geometric exclude each other (the geometric labeller reads no labels)");
  }
  if (!nodes.empty()) return pipeline::FrameSource::nodeFiles(nodes, config);
  try {
    return pipeline::FrameSource::semanticKitti(sequence, config, {labels_dir});
  } catch (const Error& e) {
    // io says which label file is missing; the ways round it are options of this tool (docs/labeller.md).
    if (std::string(e.what()).find(": missing label file (") == std::string::npos) throw;
    throw Error(std::string(e.what()) +
                ". Without labels, --labeller geometric labels the scans alone; --labels-dir DIR reads NNNNNN.label "
                "files from DIR (e.g. a segmentation network's predictions)");
  }
}

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

/// A scan with the labels of its file, as read: a PCD's or PLY's label field, or a .bin's label file.
LabeledCloud loadLabelledScan(const std::string& path, const std::string& label_path, const std::string& label_field,
                              LabelFormat format) {
  const std::optional<io::ScanFormat> scan = io::scanFormatOf(path);
  if (!scan) {
    throw Error(path + ": unknown input format '" + fs::path(path).extension().string() +
                "' (expected a KITTI .bin, a .pcd, a .ply or a .txt node file)");
  }
  if (*scan == io::ScanFormat::kKittiBin) {
    return io::readLabeledScan(path, label_path.empty() ? io::defaultLabelPath(path) : label_path, format);
  }
  if (!label_path.empty()) return io::readScanWithLabelFile(path, label_path, format);
  return io::readScanWithLabelField(path, label_field);
}

LabeledCloud loadScan(const std::string& path, const std::string& label_path, const std::string& label_field,
                      const Config& config) {
  const label::CloudLabeller labeller(config.labels, config.labeller);
  if (!labeller.readsLabelFiles()) {
    // The scan alone: no label file is opened (docs/labeller.md).
    if (!label_path.empty()) throw Error(path + ": --labeller geometric reads no label file; drop the label option");
    return labeller.apply({io::readScanPoints(path), {}});
  }
  return labeller.apply(loadLabelledScan(path, label_path, label_field, config.labels.format));
}

}  // namespace

FrameNodes loadFrameNodes(const std::string& path, const std::string& label_path, const std::string& label_field,
                          const Config& config) {
  FrameNodes f;
  auto start = std::chrono::steady_clock::now();
  if (fs::path(path).extension() == ".txt") {
    if (!label_path.empty()) throw Error(path + ": a node file carries its labels; drop the separate label file");
    io::NodeFileStats stats;
    f.nodes = io::readNodesTxt(path, LabelMap(config.labels), &stats);
    checkNodeCount(f.nodes.size(), config.graph, path);
    f.from_node_file = true;
    f.stats.unknown_label_points = stats.unknown;
    f.load_ms = msSince(start);
    return f;
  }
  LabeledCloud cloud = loadScan(path, label_path, label_field, config);
  f.points = cloud.points.size();
  f.load_ms = msSince(start);
  start = std::chrono::steady_clock::now();
  NodeExtractionResult extracted = NodeExtractor(config.cluster, effectiveLabelConfig(config), config.graph.max_nodes)
                                       .extract(cloud, config.verification, &f.footprint);
  f.extraction_ms = msSince(start);
  f.nodes = std::move(extracted.nodes);
  f.stats = extracted.stats;
  if (config.registration.pair) f.cloud = std::move(cloud);  // kept for ICP, moved: no second copy of the scan
  return f;
}

void addLabellerOption(CLI::App* cmd, std::string* labeller) {
  cmd->add_option("--labeller", *labeller,
                  "per-point classes: file (the label files), geometric (from the scan alone) or hybrid (the label "
                  "files, with the poles and trunks their label set lacks split off by geometry; docs/labeller.md); "
                  "default: the config's labeller.source")
      ->check(CLI::IsMember({"file", "geometric", "hybrid"}));
}

void checkWritable(const std::string& path, bool force) { io::checkOutputFile(path, io::overwriteIf(force)); }

void checkReportFiles(const std::string& dir, const std::vector<std::string>& files, bool force) {
  if (!fs::exists(dir)) return;
  if (!fs::is_directory(dir)) throw Error(dir + ": exists and is not a folder");
  for (const std::string& f : files) checkWritable((fs::path(dir) / f).string(), force);
}

void writeOutput(const std::string& path, const std::string& text, bool force) {
  io::writeFileAtomically(path, text, io::overwriteIf(force));
}

void warnAboutInput(const std::string& frame, const ExtractionStats& stats, int num_nodes, const char* unit) {
  const std::string name = io::escapeContent(frame, io::kNameBytes);  // a file name found in a folder
  if (stats.nonfinite_points > 0) {
    std::cerr << "warning: " << name << ": dropped " << stats.nonfinite_points
              << " points with NaN or Inf coordinates\n";
  }
  if (stats.far_points > 0) {
    std::cerr << "warning: " << name << ": dropped " << stats.far_points
              << " points farther than 1000 km from the sensor on an axis\n";
  }
  if (stats.unknown_label_points > 0) {
    std::cerr << "warning: " << name << ": ignored " << stats.unknown_label_points
              << " " << unit << " whose label id is not in the configured label set (labels.preset)\n";
  }
  if (stats.capped_nodes > 0) {
    std::cerr << "warning: " << name << ": kept the " << num_nodes << " largest clusters, dropped the "
              << stats.capped_nodes << " smallest (graph.max_nodes)\n";
  }
  if (num_nodes == 0) {
    std::cerr << "warning: " << name << ": no graph nodes (no clusters of the stable classes); it cannot be a loop\n";
  }
}

void UnknownLabels::add(const std::string& frame, size_t points) {
  ++seen_;
  if (points == 0) return;
  if (frames_++ == 0) first_ = frame;
  points_ += points;
}

void UnknownLabels::warn() const {
  if (points_ == 0) return;
  std::cerr << "warning: ignored " << points_ << " points in " << frames_ << " of " << seen_ << " frames (first: "
            << io::escapeContent(first_, io::kNameBytes) << ") whose label id is not in the configured label set (labels.preset)\n";
}

Json matrixJson(const Eigen::Matrix4d& T) {
  Json rows = Json::array();
  for (int r = 0; r < 4; ++r) {
    Json row = Json::array();
    for (int c = 0; c < 4; ++c) row.push_back(T(r, c));
    rows.push_back(row);
  }
  return rows;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  return buf;
}

std::string matrixText(const Eigen::Matrix4d& T, const std::string& indent) {
  std::string s;
  char buf[64];
  for (int r = 0; r < 4; ++r) {
    s += indent + "[";
    for (int c = 0; c < 4; ++c) {
      std::snprintf(buf, sizeof(buf), c ? " %11.6f" : "%10.6f", T(r, c));
      s += buf;
    }
    s += " ]\n";
  }
  return s;
}

std::string jsonText(const Json& j) {
  // File names need not be UTF-8; replace invalid bytes instead of failing after the work is done.
  return j.dump(2, ' ', false, Json::error_handler_t::replace);
}

Json timingJson(const StageTimes& t, double load_ms) {
  return {{"load", load_ms},
          {"extraction", t.extraction_ms},
          {"description", t.description_ms},
          {"retrieval", t.retrieval_ms},
          {"verification", t.verification_ms},
          {"refinement", t.refinement_ms},
          {"total", load_ms + t.total_ms()}};
}

Progress::Progress(std::string what, size_t total)
    : what_(std::move(what)), total_(total), enabled_(::isatty(STDERR_FILENO) != 0) {}

void Progress::update(size_t done, const std::string& extra) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  constexpr int kWidth = 30;
  const double share = total_ ? static_cast<double>(done) / total_ : 1.0;
  const int filled = static_cast<int>(share * kWidth);
  // Rate over the whole run so far: frames differ in cost, and a steady average gives a steady estimate.
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double rate = seconds > 0.0 ? static_cast<double>(done) / seconds : 0.0;
  const std::string pace = rate > 0.0 ? fixed(rate, 1) + " " + what_ + "/s, " +
                                            (done < total_ ? clockText((total_ - done) / rate) + " left"
                                                           : "took " + clockText(seconds))
                                      : "";
  std::fprintf(stderr, "\r\033[K%s [%s%s] %zu/%zu %3d%% %s%s%s", what_.c_str(), std::string(filled, '#').c_str(),
               std::string(kWidth - filled, '.').c_str(), done, total_, static_cast<int>(share * 100.0),
               pace.c_str(), pace.empty() || extra.empty() ? "" : ", ", extra.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

std::string clockText(double seconds) {
  if (!(seconds >= 0.0) || seconds > 1e9) return "?";
  const long s = static_cast<long>(seconds);
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(buf, sizeof(buf), "%ld:%02ld", s / 60, s % 60);
  return buf;
}

void Progress::clear() {
  if (enabled_ && drawn_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
  }
}

void Progress::finish() {
  if (enabled_ && drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace sgtllc::cli
