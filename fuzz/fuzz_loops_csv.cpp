// Loops CSVs of `sgtllc run --out` (io::readLoopsCsv), 16 columns or 37 with the information, against the frame
// names of a 300-frame KITTI-style sequence and a few names that need CSV quoting; then loopEdges and a write →
// re-read round trip of whatever was read. The same bytes also go through io::CsvReader alone: the records it reads
// must come back unchanged when written again with appendCsvField (RFC 4180 quoting, io/csv.h).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string_view>

#include "fuzz_support.h"
#include "sgtllc/io/csv.h"
#include "sgtllc/io/loops_csv.h"

using namespace sgtllc;

namespace {

/// Frame names 000000 … 000299: KITTI's naming. Not all 4541 of KITTI 00, since the reader maps the names afresh
/// for every file, which would take most of each execution. Then names a file system allows and CSV must quote:
/// a comma, a quote, line breaks, and a name that looks like a quoted field.
const std::vector<std::string>& frameNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    char buf[16];
    for (int i = 0; i < 300; ++i) {
      std::snprintf(buf, sizeof(buf), "%06d", i);
      v.emplace_back(buf);
    }
    for (const char* awkward : {"a,b\"c", "zz,evil,1,2", "two\nlines", "cr\r\nlf", "\"", "\"q\"", " sp "}) {
      v.emplace_back(awkward);
    }
    return v;
  }();
  return names;
}

/// CsvReader on @p text: its records, or nothing if it rejects the text (with sgtllc::Error).
std::optional<std::vector<std::vector<std::string>>> csvRecords(std::string_view text) {
  std::vector<std::vector<std::string>> records;
  if (!fuzz::readsOrRejects([&] {
        io::CsvReader reader(text, "fuzz.csv");
        for (std::vector<std::string> f; reader.next(f);) records.push_back(f);
      })) {
    return std::nullopt;
  }
  return records;
}

/// Records written back with appendCsvField read again as the same records. A record of one empty field is a
/// blank line, which the reader skips, so it is left out of the comparison.
void checkCsvRoundTrip(std::string_view text) {
  const auto records = csvRecords(text);
  if (!records) return;
  std::string written;
  std::vector<std::vector<std::string>> kept;
  for (const std::vector<std::string>& r : *records) {
    fuzz::require(!r.empty(), "a record has a field");
    if (r.size() == 1 && r[0].empty()) continue;
    for (size_t k = 0; k < r.size(); ++k) {
      if (k > 0) written += ',';
      io::appendCsvField(written, r[k]);
    }
    written += '\n';
    kept.push_back(r);
  }
  const auto again = csvRecords(written);
  fuzz::require(again.has_value() && *again == kept, "CSV records written again read back unchanged");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("loops.csv"), copy("loops-copy.csv");
  const std::vector<std::string>& names = frameNames();
  file.write(fuzz::bytesOf(data, size));
  checkCsvRoundTrip(fuzz::bytesOf(data, size));
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
