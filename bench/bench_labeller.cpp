// Geometric labeller: time per scan (median, p99 over --repeat runs of every scan) and, for scans given with a
// reference label file, per-class precision / recall / IoU against it (docs/labeller.md, BENCHMARKS.md).
//   sgtllc_bench_labeller [--repeat N] [--config FILE] [--fresh-memory] SCAN.bin[,REFERENCE.label] ...
// --config takes the labeller.* keys of a YAML configuration (the rules measured against the defaults).
// Freed memory is kept for the next scan, as the command-line tool keeps it (memory_reuse.h); --fresh-memory
// leaves glibc's defaults, which hand scan-sized buffers back to the system after every scan.
// Trunk and pole are one class in the labeller, so the reference's trunk counts as pole. A folder argument takes
// its velodyne/*.bin (timing only).
#include <algorithm>
#include <array>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sgtllc/eval/label_agreement.h"
#include "sgtllc/io/config_yaml.h"
#include "sgtllc/io/kitti.h"
#include "sgtllc/label/geometric_labeller.h"
#include "sgtllc/labels.h"
#include "sgtllc/memory_reuse.h"

namespace {

void printCounts(const char* title, const sgtllc::eval::ClassAgreement& k) {
  std::printf("%s\n  %-13s %9s %9s %9s %9s\n", title, "class", "precision", "recall", "IoU", "ref pts");
  for (int c = 0; c < sgtllc::kNumPaperClasses; ++c) {
    if (c == sgtllc::kTrunk) continue;
    std::printf("  %-13s %9.3f %9.3f %9.3f %9llu\n", c == sgtllc::kPole ? "pole+trunk" : sgtllc::kClassNames[c],
                k.precision(c), k.recall(c), k.iou(c), static_cast<unsigned long long>(k.referencePoints(c)));
  }
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 5;
  std::string config_path;
  bool fresh_memory = false;
  std::vector<std::pair<std::string, std::string>> inputs;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--repeat" && a + 1 < argc) {
      repeat = std::max(1, std::stoi(argv[++a]));
    } else if (arg == "--fresh-memory") {
      fresh_memory = true;
    } else if (arg == "--config" && a + 1 < argc) {
      config_path = argv[++a];
    } else if (std::filesystem::is_directory(arg)) {
      std::vector<std::string> bins;
      for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(arg) / "velodyne")) {
        if (e.path().extension() == ".bin") bins.push_back(e.path().string());
      }
      std::sort(bins.begin(), bins.end());
      for (const auto& b : bins) inputs.emplace_back(b, "");
    } else {
      const size_t comma = arg.find(',');
      inputs.emplace_back(arg.substr(0, comma), comma == std::string::npos ? "" : arg.substr(comma + 1));
    }
  }
  if (inputs.empty()) {
    std::fprintf(stderr, "usage: %s [--repeat N] [--config FILE] [--fresh-memory] SCAN.bin[,REFERENCE.label] ... | SEQUENCE_DIR\n", argv[0]);
    return 2;
  }
  if (!fresh_memory) sgtllc::reuseFreedMemory();
  try {
    const sgtllc::label::GeometricLabeller labeller(
        config_path.empty() ? sgtllc::LabellerConfig{} : sgtllc::io::loadConfig(config_path).labeller);
    // Wall-clock and process CPU time: on a shared machine the CPU time is what one free core would take.
    std::vector<double> times, cpu_times;
    const sgtllc::LabelMap reference_map;
    const sgtllc::eval::ClassMerge merge = sgtllc::eval::labellerMerge(sgtllc::LabelConfig{});
    sgtllc::eval::ClassAgreement all;
    size_t points = 0;
    for (const auto& [scan, ref] : inputs) {
      const std::vector<Eigen::Vector3f> cloud = sgtllc::io::readKittiBin(scan);
      points += cloud.size();
      sgtllc::label::Labelling out;
      for (int r = 0; r < repeat; ++r) {
        const auto start = std::chrono::steady_clock::now();
        const std::clock_t cpu_start = std::clock();
        out = labeller.classify(cloud);
        cpu_times.push_back(1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC);
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      }
      if (!ref.empty()) {
        sgtllc::eval::ClassAgreement k;
        k.add(out.classes, sgtllc::eval::stableClasses(sgtllc::io::readLabelFile(ref), reference_map), merge);
        all.add(k);
        printCounts((scan + " vs " + ref + " (" + std::to_string(cloud.size()) + " points, " +
                     std::to_string(out.segments) + " segments)").c_str(), k);
      }
    }
    if (inputs.size() > 1 && !inputs.front().second.empty()) printCounts("all scans with a reference", all);
    const auto report = [&](const char* what, std::vector<double> t) {
      std::sort(t.begin(), t.end());
      const auto at = [&](double q) { return t[std::min(t.size() - 1, static_cast<size_t>(q * t.size()))]; };
      std::printf("labeller %s time per scan (ms, %zu runs, %.0f points per scan on average): median %.2f, p99 %.2f, "
                  "max %.2f\n", what, t.size(), static_cast<double>(points) / inputs.size(), at(0.5), at(0.99), t.back());
    };
    report("wall-clock", times);
    report("CPU", cpu_times);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
