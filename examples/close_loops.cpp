// Loop closing embedded in a program (docs/pipeline.md): a folder of node files NAME.txt and an odometry trajectory
// in, the corrected trajectory out, as `sgtllc run --nodes DIR --odometry ODOM --calib CALIB --config CONFIG
// --out-trajectory OUT` writes it (KITTI 00: `make kitti00`'s inputs; a test compares the two files).
//   build/examples/sgtllc_close_loops NODE_DIR ODOMETRY CALIB CONFIG OUT
#include <algorithm>
#include <filesystem>
#include <iostream>

#include "sgtllc/io/config_yaml.h"
#include "sgtllc/io/nodes.h"
#include "sgtllc/io/trajectory.h"
#include "sgtllc/pipeline/loop_closing_pipeline.h"

int main(int argc, char** argv) {
  using namespace sgtllc;
  if (argc != 6) return std::cerr << "usage: sgtllc_close_loops NODE_DIR ODOMETRY CALIB CONFIG OUT\n", 2;
  try {
    const Config config = io::loadConfig(argv[4]);
    const io::Trajectory odometry = io::readTrajectory(argv[2], argv[3], io::PoseFrame::kCam0).trajectory;
    std::vector<std::filesystem::path> files;  // the frames, in name order
    for (const auto& entry : std::filesystem::directory_iterator(argv[1])) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    const LabelMap labels(config.labels);
    pipeline::LoopClosingPipeline closer(config);
    for (size_t i = 0; i < files.size(); ++i) {
      std::vector<Node> nodes = io::readNodesTxt(files[i].string(), labels);
      const auto f = closer.addNodes(std::move(nodes), odometry.poses.at(i), files[i].stem().string());
      if (f.loop) std::cout << "loop " << f.loop->query << " -> " << f.loop->match << "\n";
    }
    const pipeline::Closing& closing = closer.finish();
    io::writeTrajectory(argv[5], io::withPoses(odometry, closing.poses));
    std::cout << closer.loops().size() << " loops, " << closing.result.num_accepted << " accepted\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
