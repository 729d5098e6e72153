// Minimal use of the library: run the online detector over KITTI scans given on the command line, in order,
// and print each loop closure with its pose. Build: part of the project (target sgtllc_example).
//   build/examples/sgtllc_example data/kitti/00/velodyne/000052.bin data/kitti/00/velodyne/004501.bin
#include <iostream>

#include "sgtllc/detector.h"
#include "sgtllc/io/kitti.h"

int main(int argc, char** argv) {
  sgtllc::Config config;
  config.retrieval.exclude_recent = 1;  // a handful of scans: let every older scan be a candidate
  sgtllc::LoopDetector detector(config);
  try {
    for (int a = 1; a < argc; ++a) {
      const std::string bin = argv[a];
      const sgtllc::LabeledCloud scan = sgtllc::io::readLabeledScan(bin, sgtllc::io::defaultLabelPath(bin));
      const sgtllc::FrameResult r = detector.process(scan);
      std::cout << "frame " << r.frame << ": " << r.num_nodes << " nodes";
      if (const sgtllc::Candidate* loop = r.loop()) {
        std::cout << ", loop with frame " << loop->frame << " (score " << loop->match.score
                  << "), T_match_query =\n"
                  << loop->match.T_match_query;
      }
      std::cout << "\n";
    }
  } catch (const sgtllc::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
