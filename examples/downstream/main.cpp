// Is QUERY a revisit of MATCH? Two labelled KITTI-layout scans through sgtllc::comparePair, from a project that
// adds sgtllc with add_subdirectory (CMakeLists.txt beside this file).
//   uses_sgtllc data/kitti/00/velodyne/004501.bin data/kitti/00/velodyne/000052.bin
#include <iostream>

#include <sgtllc/detector.h>
#include <sgtllc/io/kitti.h>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: uses_sgtllc QUERY.bin MATCH.bin (labels in ../labels/NAME.label)\n";
    return 2;
  }
  try {
    const auto scan = [](const std::string& bin) {
      return sgtllc::io::readLabeledScan(bin, sgtllc::io::defaultLabelPath(bin));
    };
    const sgtllc::PairResult r = sgtllc::comparePair(scan(argv[1]), scan(argv[2]));
    std::cout << "loop " << (r.is_loop ? "YES" : "no") << ", score " << r.match.score << ", inliers "
              << r.match.inliers.size() << "\nT_match_query =\n" << r.match.T_match_query << "\n";
  } catch (const sgtllc::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
