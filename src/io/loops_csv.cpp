// The loops CSV of `sgtllc run --out` (loops_csv.h): writer and reader share the column list below.
#include "sgtllc/io/loops_csv.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>
#include <tuple>
#include <unordered_map>

#include <Eigen/SVD>

#include "file_util.h"
#include "sgtllc/io/csv.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/types.h"

namespace sgtllc::io {
namespace {

constexpr size_t kColumns = 16;
constexpr size_t kInformationColumns = 21;
constexpr size_t kFirstMatrixColumn = 4;
constexpr double kOrthonormalTolerance = 1e-3;  // six decimals leave |RᵀR − I| ~ 1e-6

void appendFixed6(std::string& out, double v) {
  // Room for every finite double: `%.6f` of 1.8e308 has 309 integer digits (a 64-byte buffer cut numbers of
  // 1e63 and more short, so they read back smaller; fuzz_loops_csv found this, fuzz/README.md).
  char buf[std::numeric_limits<double>::max_exponent10 + 16];
  std::snprintf(buf, sizeof(buf), "%.6f", v);
  out += buf;
}

std::vector<std::string> headerColumns(bool with_information) {
  std::vector<std::string> h = loopsCsvColumns();
  if (with_information) {
    const std::vector<std::string>& more = loopsCsvInformationColumns();
    h.insert(h.end(), more.begin(), more.end());
  }
  return h;
}

std::string headerLine(bool with_information = false) {
  std::string h;
  for (const std::string& c : headerColumns(with_information)) h += (h.empty() ? "" : ",") + c;
  return h;
}

/// The information fields of a row (21 strings): empty, or the symmetric matrix they list. Throws naming @p at.
std::optional<backend::Matrix6d> parseInformation(const std::vector<std::string>& f, const std::string& at) {
  const std::vector<std::string>& names = loopsCsvInformationColumns();
  size_t empty = 0;
  for (size_t k = kColumns; k < f.size(); ++k) empty += f[k].empty();
  if (empty == kInformationColumns) return std::nullopt;
  backend::Matrix6d information;
  size_t k = kColumns;
  for (int r = 0; r < 6; ++r) {
    for (int c = r; c < 6; ++c, ++k) {
      double v = 0.0;
      if (!detail::parseReal(f[k], v) || !std::isfinite(v)) {
        throw Error(at + ": column " + names[k - kColumns] + ": " + quoteContent(f[k]) +
                    " is not a finite number (give all 21 information entries or none)");
      }
      if (r == c && v < 0.0) throw Error(at + ": column " + names[k - kColumns] + ": negative information diagonal");
      information(r, c) = information(c, r) = v;
    }
  }
  return information;
}

}  // namespace

const std::vector<std::string>& loopsCsvColumns() {
  static const std::vector<std::string> columns = {"query", "match", "score", "score_c", "r11", "r12",
                                                   "r13",   "tx",    "r21",   "r22",     "r23", "ty",
                                                   "r31",   "r32",   "r33",   "tz"};
  return columns;
}

const std::vector<std::string>& loopsCsvInformationColumns() {
  static const std::vector<std::string> columns = [] {
    std::vector<std::string> c;
    for (int r = 1; r <= 6; ++r) {
      for (int k = r; k <= 6; ++k) c.push_back("i" + std::to_string(r) + std::to_string(k));
    }
    return c;
  }();
  return columns;
}

std::string loopsCsvText(const std::vector<LoopRecord>& loops, bool with_information) {
  std::string out = headerLine(with_information) + "\n";
  for (const LoopRecord& l : loops) {
    appendCsvField(out, l.query);
    out += ',';
    appendCsvField(out, l.match);
    out += ',';
    appendFixed6(out, l.score);
    out += ',';
    appendFixed6(out, l.score_c);
    for (int k = 0; k < 12; ++k) {
      out += ',';
      appendFixed6(out, l.T_match_query(k / 4, k % 4));
    }
    if (with_information) {
      for (int r = 0; r < 6; ++r) {
        for (int c = r; c < 6; ++c) {
          out += ',';
          if (l.information) detail::appendShortest(out, (*l.information)(r, c));
        }
      }
    }
    out += '\n';
  }
  return out;
}

std::vector<LoopRecord> readLoopsCsv(const std::string& path, const std::vector<std::string>& frame_names) {
  const std::string text = detail::readWholeFile(path);
  std::unordered_map<std::string_view, int> index_of;
  for (size_t i = 0; i < frame_names.size(); ++i) index_of.emplace(frame_names[i], static_cast<int>(i));
  const std::vector<std::string>& columns = loopsCsvColumns();

  std::vector<LoopRecord> loops;
  CsvReader reader(text, path);
  std::vector<std::string> f;
  if (!reader.next(f)) {
    throw Error(path + ": empty file (expected the loops CSV header '" + headerLine() + "')");
  }
  const bool with_information = f == headerColumns(true);
  if (f != headerColumns(false) && !with_information) {
    std::string line;
    for (const std::string& field : f) line += (line.empty() ? "" : ",") + csvField(field);
    throw Error(reader.at() + ": header " + quoteContent(line) + " is not the loops CSV header '" + headerLine() +
                "' (optionally followed by the information columns i11,…,i66)");
  }
  while (reader.next(f)) {
    const std::string at = reader.at();
    const size_t expected = with_information ? kColumns + kInformationColumns : kColumns;
    if (f.size() != expected) {
      throw Error(at + ": " + std::to_string(f.size()) + " columns, expected " + std::to_string(expected) +
                  " (" + (with_information ? "the header's" : headerLine()) + ")");
    }
    LoopRecord l;
    l.query = f[0];
    l.match = f[1];
    for (const auto& [name, index, role] : {std::tuple{&l.query, &l.query_index, "query"},
                                            std::tuple{&l.match, &l.match_index, "match"}}) {
      const auto it = index_of.find(*name);
      if (it == index_of.end()) {
        throw Error(at + ": unknown " + role + " frame " + quoteContent(*name) + " (not one of the sequence's " +
                    std::to_string(frame_names.size()) + " frames)");
      }
      *index = it->second;
    }
    if (l.query_index == l.match_index) throw Error(at + ": loop of frame " + quoteContent(l.query) + " with itself");
    double v[kColumns] = {};
    for (size_t k = 2; k < kColumns; ++k) {
      if (!detail::parseReal(f[k], v[k]) || !std::isfinite(v[k])) {
        throw Error(at + ": column " + columns[k] + ": " + quoteContent(f[k]) + " is not a finite number");
      }
    }
    l.score = v[2];
    l.score_c = v[3];
    for (int k = 0; k < 12; ++k) l.T_match_query(k / 4, k % 4) = v[kFirstMatrixColumn + static_cast<size_t>(k)];
    const Eigen::Matrix3d R = l.T_match_query.topLeftCorner<3, 3>();
    const double err = (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (err > kOrthonormalTolerance || R.determinant() <= 0.0) {
      throw Error(at + ": r11..r33 is not a rotation (|RᵀR − I| = " + std::to_string(err) + ", det " +
                  std::to_string(R.determinant()) + ")");
    }
    if (with_information) l.information = parseInformation(f, at);
    loops.push_back(l);
  }
  return loops;
}

std::vector<backend::Edge> loopEdges(const std::vector<LoopRecord>& loops, const backend::Matrix6d& information) {
  std::vector<backend::Edge> edges;
  edges.reserve(loops.size());
  for (const LoopRecord& l : loops) {
    if (l.query_index < 0 || l.match_index < 0) {
      throw Error("loop " + quoteContent(l.query) + " -> " + quoteContent(l.match) + " has no frame indices (read it with readLoopsCsv)");
    }
    backend::Edge e;
    e.from = l.match_index;
    e.to = l.query_index;
    // Nearest rotation (Frobenius norm): U·Vᵀ of the SVD; the determinant was checked positive when reading.
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(l.T_match_query.topLeftCorner<3, 3>(),
                                                Eigen::ComputeFullU | Eigen::ComputeFullV);
    e.T_from_to.linear() = svd.matrixU() * svd.matrixV().transpose();
    e.T_from_to.translation() = l.T_match_query.topRightCorner<3, 1>();
    e.information = l.information.value_or(information);
    e.kind = backend::EdgeKind::kLoop;
    edges.push_back(e);
  }
  return edges;
}

}  // namespace sgtllc::io
