#include "sgtllc/pipeline/frame_source.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <memory>

#include "elapsed.h"
#include "frame_reducer.h"
#include "process_frame.h"
#include "sgtllc/accumulate/scan_accumulator.h"
#include "sgtllc/graph.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/sequence.h"
#include "sgtllc/parallel.h"

namespace fs = std::filesystem;

namespace sgtllc::pipeline {

FrameSource FrameSource::semanticKitti(const std::string& dir, const Config& config,
                                       const FrameSourceOptions& options) {
  auto reducer = std::make_shared<const FrameReducer>(config);
  const bool geometric = !reducer->readsLabels();
  auto seq = std::make_shared<io::SequenceDir>(
      dir, io::SequenceLabels{!geometric, options.labels_dir, config.labels.format});
  FrameSource source;
  for (size_t i = 0; i < seq->size(); ++i) source.names_.push_back(seq->frameName(i));
  source.read_ = [seq, geometric](size_t i) {
    LabeledCloud cloud = seq->load(i);
    // No label file is read: placeholders keep points and labels paired (scan accumulation) until the labeller
    // replaces them in reduce_.
    if (geometric) cloud.labels.assign(cloud.points.size(), 0);
    return cloud;
  };
  // The geometric labeller labels the cloud that is reduced: an accumulated frame is labelled once, merged.
  source.reduce_ = [reducer](const LabeledCloud& input) { return reducer->reduce(input); };
  source.loader_ = [read = source.read_, reduce = source.reduce_](size_t i) {
    const auto start = std::chrono::steady_clock::now();
    const LabeledCloud cloud = read(i);
    const double load_ms = msSince(start);
    LoadedFrame f = reduce(cloud);
    f.load_ms = load_ms;
    return f;
  };
  return source;
}

FrameSource FrameSource::nodeFiles(const std::string& dir, const Config& config) {
  if (!fs::is_directory(dir)) throw Error(dir + ": no such directory (expected node files NAME.txt)");
  FrameSource source;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".txt") {
      source.names_.push_back(entry.path().stem().string());
    }
  }
  std::sort(source.names_.begin(), source.names_.end());
  if (source.names_.empty()) throw Error(dir + ": no node files (NAME.txt)");
  auto labels = std::make_shared<LabelMap>(config.labels);
  const std::vector<std::string> names = source.names_;
  source.loader_ = [dir, names, labels, graph = config.graph](size_t i) {
    LoadedFrame f;
    const auto start = std::chrono::steady_clock::now();
    io::NodeFileStats stats;
    const std::string path = (fs::path(dir) / (names.at(i) + ".txt")).string();
    f.nodes = io::readNodesTxt(path, *labels, &stats);
    checkNodeCount(f.nodes.size(), graph, path);  // ready-made nodes are never dropped silently
    f.stats.unknown_label_points = stats.unknown;
    f.load_ms = msSince(start);
    return f;
  };
  return source;
}

long FrameSource::number(size_t i) const {
  const std::string& n = name(i);
  if (n.empty() || n.size() > 12 || !std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return -1;
  }
  return std::stol(n);
}

LoadedFrame FrameSource::load(size_t i) const {
  if (scans_ == 1) return loader_(i);
  if (i >= size()) throw Error("frame " + std::to_string(i) + " is out of range");
  ScanAccumulator buffer(scans_);
  const size_t first = i + 1 >= static_cast<size_t>(scans_) ? i + 1 - static_cast<size_t>(scans_) : 0;
  LabeledCloud merged;
  double load_ms = 0.0;
  for (size_t j = first; j <= i; ++j) {
    const auto start = std::chrono::steady_clock::now();
    LabeledCloud scan = read_(j);
    if (j == i) load_ms = msSince(start);  // as when streaming: the scan of this frame
    merged = buffer.add(std::move(scan), poses_[j]);
  }
  LoadedFrame f = reduce_(merged);
  f.load_ms = load_ms;
  f.buffer_bytes = buffer.bytes();
  return f;
}

void FrameSource::accumulate(int scans, std::vector<Eigen::Isometry3d> T_world_scan) {
  const ScanAccumulator check(scans);  // the range of scans, with the core's message
  if (!read_) throw Error("scan accumulation needs scans (velodyne/ and labels/), not node files");
  if (T_world_scan.size() != size()) {
    throw Error("scan accumulation: " + std::to_string(T_world_scan.size()) + " poses for " +
                std::to_string(size()) + " frames");
  }
  scans_ = scans;
  poses_ = std::move(T_world_scan);
}

namespace {

/// Frames first … first + count − 1 of an accumulating source: raw scans read in parallel, merged in frame order
/// through @p buffer (which carries the previous batch's scans over), merged scans reduced in parallel.
void loadAccumulated(const std::function<LabeledCloud(size_t)>& read,
                     const std::function<LoadedFrame(const LabeledCloud&)>& reduce,
                     const std::vector<Eigen::Isometry3d>& poses, ScanAccumulator& buffer, size_t first, int threads,
                     std::vector<LoadedFrame>& frames, std::vector<std::exception_ptr>& errors) {
  const size_t count = frames.size();
  std::vector<LabeledCloud> clouds(count);
  std::vector<double> load_ms(count, 0.0);
  parallelFor(static_cast<int>(count), threads, [&](int k) {
    try {
      const auto start = std::chrono::steady_clock::now();
      clouds[k] = read(first + k);
      load_ms[k] = msSince(start);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  std::vector<double> accumulate_ms(count, 0.0);
  std::vector<size_t> bytes(count, 0);
  size_t merged = 0;  // frames merged; the first read error stops there, as if the files ended
  for (; merged < count && !errors[merged]; ++merged) {
    const auto start = std::chrono::steady_clock::now();
    clouds[merged] = buffer.add(std::move(clouds[merged]), poses[first + merged]);
    accumulate_ms[merged] = msSince(start);
    bytes[merged] = buffer.bytes();
  }
  parallelFor(static_cast<int>(merged), threads, [&](int k) {
    try {
      frames[k] = reduce(clouds[k]);
      frames[k].load_ms = load_ms[k];
      frames[k].accumulate_ms = accumulate_ms[k];
      frames[k].buffer_bytes = bytes[k];
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
}

}  // namespace

void streamFrames(const FrameSource& source, int threads, const std::function<void(size_t, LoadedFrame&)>& on_frame) {
  const size_t batch = static_cast<size_t>(std::max(1, 4 * std::max(1, threads)));
  std::vector<LoadedFrame> frames;
  std::vector<std::exception_ptr> errors;
  std::unique_ptr<ScanAccumulator> buffer;
  if (source.scans_ > 1) buffer = std::make_unique<ScanAccumulator>(source.scans_);
  for (size_t first = 0; first < source.size(); first += batch) {
    const size_t count = std::min(batch, source.size() - first);
    frames.assign(count, LoadedFrame{});
    errors.assign(count, nullptr);
    if (buffer) {
      loadAccumulated(source.read_, source.reduce_, source.poses_, *buffer, first, threads, frames, errors);
    } else {
      parallelFor(static_cast<int>(count), threads, [&](int k) {
        try {
          frames[k] = source.load(first + k);
        } catch (...) {
          errors[k] = std::current_exception();
        }
      });
    }
    for (size_t k = 0; k < count; ++k) {
      if (errors[k]) std::rethrow_exception(errors[k]);
      on_frame(first + k, frames[k]);
    }
  }
}

void streamSequence(const FrameSource& source, LoopDetector& detector, int threads,
                    const std::function<void(size_t, const LoadedFrame&, const FrameResult&)>& on_frame) {
  streamFrames(source, threads, [&](size_t index, LoadedFrame& frame) {
    const FrameResult r = processFrame(detector, frame);
    on_frame(index, frame, r);
  });
}

}  // namespace sgtllc::pipeline
