// Lists of scan pairs for `sgtllc pair --list` (scan_pairs.h).
#include "sgtllc/io/scan_pairs.h"

#include <filesystem>

#include "file_util.h"
#include "sgtllc/io/csv.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/types.h"

namespace sgtllc::io {

std::vector<ScanPair> readScanPairs(const std::string& path) {
  const std::string text = detail::readWholeFile(path);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  const auto resolve = [&](const std::string& field) {
    const std::filesystem::path p(field);
    return p.is_absolute() || folder.empty() ? field : (folder / p).string();
  };
  std::vector<ScanPair> pairs;
  CsvReader reader(text, path);
  std::vector<std::string> f;
  bool first = true;
  while (reader.next(f)) {
    const bool header = first && f.size() == 2 && f[0] == "query" && f[1] == "match";
    first = false;
    if (header || (!f.empty() && !f[0].empty() && f[0][0] == '#')) continue;
    if (f.size() != 2) {
      throw Error(reader.at() + ": " + std::to_string(f.size()) + " fields, expected two: QUERY,MATCH (a path " +
                  "holding a comma is quoted)");
    }
    for (const std::string& field : f) {
      if (field.empty()) throw Error(reader.at() + ": an empty path");
      if (field.find('\0') != std::string::npos) {
        throw Error(reader.at() + ": the path " + quoteContent(field) + " holds a NUL byte");
      }
    }
    pairs.push_back({resolve(f[0]), resolve(f[1]), reader.line()});
  }
  if (pairs.empty()) throw Error(path + ": no pair (one a line: QUERY,MATCH)");
  return pairs;
}

}  // namespace sgtllc::io
