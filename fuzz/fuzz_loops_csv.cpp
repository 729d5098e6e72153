// Loops CSVs of `sgtllc run --out` (io::readLoopsCsv), 16 columns or 37 with the information, against the frame
// names of a 300-frame KITTI-style sequence; then loopEdges and a write → re-read round trip of whatever was read.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "fuzz_support.h"
#include "sgtllc/io/loops_csv.h"

using namespace sgtllc;

namespace {

/// Frame names 000000 … 000299: KITTI's naming. Not all 4541 of KITTI 00, since the reader maps the names afresh
/// for every file, which would take most of each execution.
const std::vector<std::string>& frameNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    char buf[16];
    for (int i = 0; i < 300; ++i) {
      std::snprintf(buf, sizeof(buf), "%06d", i);
      v.emplace_back(buf);
    }
    return v;
  }();
  return names;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("loops.csv"), copy("loops-copy.csv");
  const std::vector<std::string>& names = frameNames();
  file.write(fuzz::bytesOf(data, size));
  std::vector<io::LoopRecord> loops;
  if (!fuzz::readsOrRejects([&] { loops = io::readLoopsCsv(file.path(), names); })) return 0;
  bool with_information = false;
  for (const io::LoopRecord& l : loops) {
    fuzz::require(l.query_index >= 0 && l.query_index < static_cast<int>(names.size()) && l.match_index >= 0 &&
                      l.match_index < static_cast<int>(names.size()),
                  "frame indices in the sequence");
    fuzz::require(names[l.query_index] == l.query && names[l.match_index] == l.match, "indices name the frames");
    fuzz::require(l.query_index != l.match_index, "no loop of a frame with itself");
    fuzz::require(std::isfinite(l.score) && std::isfinite(l.score_c) && l.T_match_query.allFinite(), "finite values");
    if (l.information) {
      with_information = true;
      const backend::Matrix6d& I = *l.information;
      fuzz::require(I.allFinite() && I == I.transpose() && (I.diagonal().array() >= 0.0).all(),
                    "information finite, symmetric, non-negative diagonal");
    }
  }
  for (const backend::Edge& e : io::loopEdges(loops, backend::Matrix6d::Identity())) {
    const Eigen::Matrix3d R = e.T_from_to.linear();
    fuzz::require(R.allFinite() && (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-9,
                  "loop edges carry rotations");
  }

  // Written back (six decimals for the numbers, shortest exact for the information) and read again.
  copy.write(io::loopsCsvText(loops, with_information));
  const std::vector<io::LoopRecord> again = io::readLoopsCsv(copy.path(), names);
  fuzz::require(again.size() == loops.size(), "round trip keeps the loop count");
  for (size_t i = 0; i < loops.size(); ++i) {
    const io::LoopRecord &a = again[i], &l = loops[i];
    fuzz::require(a.query == l.query && a.match == l.match, "round trip keeps the frame names");
    fuzz::require(a.information == l.information, "round trip keeps the information exactly");
    const auto close = [](double x, double y) { return std::abs(x - y) <= 5e-7 + 1e-15 * std::abs(y); };
    fuzz::require(close(a.score, l.score) && close(a.score_c, l.score_c), "round trip keeps the scores to 6 decimals");
    for (int k = 0; k < 12; ++k) {
      fuzz::require(close(a.T_match_query(k / 4, k % 4), l.T_match_query(k / 4, k % 4)),
                    "round trip keeps the pose to 6 decimals");
    }
  }
  return 0;
}
