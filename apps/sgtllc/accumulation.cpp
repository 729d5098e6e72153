#include "accumulation.h"

#include <algorithm>
#include <filesystem>

#include "sgtllc/eval/sequence_eval.h"

namespace fs = std::filesystem;

namespace sgtllc::cli {

void addAccumulateOption(CLI::App& cmd, int& scans) {
  cmd.add_option("--accumulate", scans,
                 "merge each scan with the N-1 scans before it, moved into its frame by the --odometry poses (or "
                 "SEQ_DIR/poses.txt through calib.txt), before node extraction: for narrow sensors such as the "
                 "Livox Mid-70 (configs/mcd.yaml: 10). 1 = off")
      ->check(CLI::Range(1, pipeline::kMaxAccumulatedScans))
      ->capture_default_str();
}

void applyAccumulation(pipeline::FrameSource& source, int scans, const Odometry* odometry, const std::string& sequence,
                       const std::string& calib, io::PoseFrame frame) {
  if (scans <= 1) return;
  if (odometry) {
    source.accumulate(scans, odometry->poses);
    return;
  }
  const std::string poses = (fs::path(sequence) / "poses.txt").string();
  if (!fs::exists(poses)) {
    throw Error(poses + ": missing; --accumulate needs one pose per frame: give --odometry ODOM.txt or add poses.txt");
  }
  source.accumulate(scans, readOdometry(poses, sequenceCalib(calib, sequence), frame, source.size()).poses);
}

void AccumulationCost::add(const pipeline::LoadedFrame& frame) {
  ms.push_back(frame.accumulate_ms);
  max_bytes = std::max(max_bytes, frame.buffer_bytes);
}

Json AccumulationCost::json(int scans) const {
  return {{"scans", scans},
          {"ms_per_frame_median", eval::percentile(ms, 0.5)},
          {"ms_per_frame_p99", eval::percentile(ms, 0.99)},
          {"buffer_bytes_max", max_bytes}};
}

std::string AccumulationCost::text(int scans) const {
  return "accumulated " + std::to_string(scans) + " scans per frame: merging median " +
         fixed(eval::percentile(ms, 0.5), 2) + " ms, p99 " + fixed(eval::percentile(ms, 0.99), 2) +
         " ms per frame; buffer at most " + fixed(static_cast<double>(max_bytes) / 1e6, 1) + " MB\n";
}

}  // namespace sgtllc::cli
