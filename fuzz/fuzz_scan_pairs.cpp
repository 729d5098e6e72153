// Lists of scan pairs for `sgtllc pair --list` (io::readScanPairs): CSV records QUERY,MATCH, comments, a header,
// paths taken from the list's folder. What it reads must come back unchanged when written again as CSV records.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_support.h"
#include "sgtllc/io/csv.h"
#include "sgtllc/io/scan_pairs.h"

using namespace sgtllc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const fuzz::ScratchFile file("scan_pairs.txt");
  static const fuzz::ScratchFile again("scan_pairs_again.txt");
  file.write(fuzz::bytesOf(data, size));
  std::vector<io::ScanPair> pairs;
  if (!fuzz::readsOrRejects([&] { pairs = io::readScanPairs(file.path()); })) return 0;
  fuzz::require(!pairs.empty(), "a list that reads names a pair");
  std::string text;
  for (const io::ScanPair& p : pairs) {
    for (const std::string* path : {&p.query, &p.match}) {
      fuzz::require(!path->empty() && path->find('\0') == std::string::npos, "paths are not empty, hold no NUL");
      // In an absolute folder (the scratch file's, /dev/shm by default) every path read is absolute: the list's
      // folder or the path's own.
      fuzz::require(file.path()[0] != '/' || (*path)[0] == '/', "paths are taken from the list's folder");
    }
    io::appendCsvField(text, p.query);
    text += ',';
    io::appendCsvField(text, p.match);
    text += '\n';
  }
  again.write(text);
  const std::vector<io::ScanPair> back = io::readScanPairs(again.path());
  fuzz::require(back.size() == pairs.size(), "written again, the list reads back as many pairs");
  for (size_t k = 0; k < back.size(); ++k) {
    fuzz::require(back[k].query == pairs[k].query && back[k].match == pairs[k].match, "and the same paths");
  }
  return 0;
}
