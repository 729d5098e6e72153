#include "sgtllc/eval/frame_source.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <memory>

#include "sgtllc/graph.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/sequence.h"
#include "sgtllc/label/geometric_labeller.h"
#include "sgtllc/parallel.h"

namespace fs = std::filesystem;

namespace sgtllc::eval {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

FrameSource FrameSource::semanticKitti(const std::string& dir, const Config& config,
                                       const FrameSourceOptions& options) {
  const bool geometric = config.labeller.source == LabelSource::kGeometric;
  auto seq = std::make_shared<io::SequenceDir>(dir, io::SequenceLabels{!geometric, options.labels_dir});
  const LabelConfig labels = effectiveLabelConfig(config);
  auto extractor = std::make_shared<NodeExtractor>(config.cluster, labels, config.graph.max_nodes);
  auto store = std::make_shared<CloudStore>(config.registration, labels);  // prepare() only
  std::shared_ptr<const label::GeometricLabeller> labeller;
  if (geometric) labeller = std::make_shared<const label::GeometricLabeller>(config.labeller);
  FrameSource source;
  for (size_t i = 0; i < seq->size(); ++i) source.names_.push_back(seq->frameName(i));
  source.loader_ = [seq, extractor, store, labeller](size_t i) {
    LoadedFrame f;
    auto start = std::chrono::steady_clock::now();
    LabeledCloud cloud = seq->load(i);
    f.load_ms = msSince(start);
    start = std::chrono::steady_clock::now();
    if (labeller) cloud = label::labelCloud(std::move(cloud.points), *labeller);
    NodeExtractionResult r = extractor->extract(cloud);
    f.extraction_ms = msSince(start);  // with the geometric labeller, labelling included
    f.nodes = std::move(r.nodes);
    f.stats = r.stats;
    start = std::chrono::steady_clock::now();
    f.clouds = store->prepare(cloud);
    f.clouds_ms = msSince(start);
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

void streamSequence(const FrameSource& source, LoopDetector& detector, int threads,
                    const std::function<void(size_t, const LoadedFrame&, const FrameResult&)>& on_frame) {
  const size_t batch = static_cast<size_t>(std::max(1, 4 * std::max(1, threads)));
  std::vector<LoadedFrame> frames;
  std::vector<std::exception_ptr> errors;
  for (size_t first = 0; first < source.size(); first += batch) {
    const size_t count = std::min(batch, source.size() - first);
    frames.assign(count, LoadedFrame{});
    errors.assign(count, nullptr);
    parallelFor(static_cast<int>(count), threads, [&](int k) {
      try {
        frames[k] = source.load(first + k);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    });
    for (size_t k = 0; k < count; ++k) {
      if (errors[k]) std::rethrow_exception(errors[k]);
      FrameResult r = detector.process(std::move(frames[k].nodes), std::move(frames[k].clouds));
      r.timing.extraction_ms = frames[k].extraction_ms;
      r.timing.refinement_ms += frames[k].clouds_ms;
      r.extraction = frames[k].stats;
      on_frame(first + k, frames[k], r);
    }
  }
}

}  // namespace sgtllc::eval
