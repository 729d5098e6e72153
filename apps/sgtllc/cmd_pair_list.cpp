// `sgtllc pair --list LIST`: many pairs in one process (pair_compare.h). A script that calls `sgtllc pair` once a
// pair pays the process start and the first touch of a scan's memory every time (BENCHMARKS.md, "Whole process").
#include <algorithm>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "pair_compare.h"
#include "sgtllc/io/csv.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/io/scan_pairs.h"
#include "sgtllc/parallel.h"

namespace sgtllc::cli {
namespace {

/// Nine decimals: the pose's translation to the nanometre, its rotation's entries to 1e-9.
std::string number(double v) { return fixed(v, 9); }

std::string csvHeader() {
  std::string h = "query,match,loop,score,score_c,inliers,nodes_query,nodes_match,path,rejection,refinement";
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) h += ",T" + std::to_string(r) + std::to_string(c);
  }
  return h + ",error";
}

/// One JSON object on one line; bytes that are not UTF-8 (from file names) are replaced, as jsonText does.
std::string jsonLine(const Json& j) { return j.dump(-1, ' ', false, Json::error_handler_t::replace); }

/// A row of csvHeader(): the pair's decision, scores and T_match_query (3 × 4, row-major), or its error.
std::string csvRow(const io::ScanPair& pair, const PairResult* r, const std::string& error) {
  std::string row;
  io::appendCsvField(row, pair.query);
  row += ',';
  io::appendCsvField(row, pair.match);
  if (r) {
    const MatchResult& m = r->match;
    row += std::string(",") + (r->is_loop ? "1" : "0") + "," + number(m.score) + "," + number(m.score_c) + "," +
           std::to_string(m.inliers.size()) + "," + std::to_string(r->query_nodes.size()) + "," +
           std::to_string(r->match_nodes.size()) + "," + (m.by_consistency ? "consistency" : "descriptors") + "," +
           rejectionName(m.rejection) + "," + (r->refinement ? refinementStatusName(r->refinement->status) : "none");
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 4; ++j) row += "," + number(m.T_match_query(i, j));
    }
    row += ",";
  } else {
    row += std::string(22, ',');  // the 9 result columns and the 12 of the pose left empty
    io::appendCsvField(row, error);
  }
  return row;
}

}  // namespace

void runPairList(const std::string& list, const std::string& label_field, const Config& given, bool json,
                 int threads) {
  const std::vector<io::ScanPair> pairs = io::readScanPairs(list);
  Config config = given;
  if (threads > 1) config.threads = 1;  // the pairs share the cores, not each pair's stages
  if (!json) std::cout << csvHeader() << "\n";
  const auto filesOf = [&](const io::ScanPair& pair) { return PairFiles{pair.query, pair.match, "", "", label_field}; };
  // A batch of `threads` pairs at once; its warnings and rows are printed afterwards, in the list's order.
  const size_t batch = static_cast<size_t>(std::max(1, threads));
  size_t failed = 0;
  for (size_t first = 0; first < pairs.size(); first += batch) {
    const int n = static_cast<int>(std::min(batch, pairs.size() - first));
    std::vector<std::optional<ComparedPair>> compared(static_cast<size_t>(n));
    std::vector<std::string> errors(static_cast<size_t>(n));
    parallelFor(n, n, [&](int k) {
      try {
        compared[k] = compareFiles(filesOf(pairs[first + k]), config, false);
      } catch (const std::exception& e) {
        errors[k] = e.what();
      }
    });
    for (int k = 0; k < n; ++k) {
      const io::ScanPair& pair = pairs[first + k];
      if (const std::optional<ComparedPair>& c = compared[k]) {
        warnInputs(filesOf(pair), *c);
        if (json) {
          std::cout << jsonLine(pairJson(pair.query, pair.match, c->result, config, c->load_ms)) << "\n";
        } else {
          std::cout << csvRow(pair, &c->result, "") << "\n";
        }
        continue;
      }
      ++failed;
      std::cerr << "sgtllc: error: " << list << ":" << pair.line << ": " << io::escapeControls(errors[k]) << "\n";
      if (json) {
        std::cout << jsonLine({{"query", pair.query}, {"match", pair.match}, {"error", errors[k]}}) << "\n";
      } else {
        std::cout << csvRow(pair, nullptr, io::escapeControls(errors[k])) << "\n";
      }
    }
    std::cout.flush();
  }
  if (failed > 0) {
    throw Error(list + ": " + std::to_string(failed) + " of " + std::to_string(pairs.size()) +
                " pairs could not be compared (their errors are above and in their rows)");
  }
}

}  // namespace sgtllc::cli
