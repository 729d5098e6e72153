/// @file scan_pairs.h
/// @brief Lists of scan pairs for `sgtllc pair --list`: many pairs compared in one process.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace sgtllc::io {

/// One pair of a list: the query scan, the scan it may revisit, and the list's line that named them.
struct ScanPair {
  std::string query;
  std::string match;
  size_t line = 0;
};

/// The pairs of a list file: one pair a record, `QUERY,MATCH` as CSV (csv.h: a path holding a comma, a quote or a
/// newline is quoted). Records whose first field starts with `#` are comments, blank lines are skipped, and a
/// first record `query,match` is a header. A relative path is taken from the list's folder, so a list moves with
/// its scans; an absolute one stays as it is. Throws sgtllc::Error naming the file (and the line) if it cannot be
/// read, a record has other than two fields, a field is empty or holds a NUL byte, or it names no pair.
std::vector<ScanPair> readScanPairs(const std::string& path);

}  // namespace sgtllc::io
