// KITTI / SemanticKITTI readers. Formats: data/README.md "Formats (short)".
#include "sgtllc/io/kitti.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <string_view>

#include <Eigen/LU>

#include "file_util.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::io {
namespace {

namespace fs = std::filesystem;
using detail::FilePtr;
using detail::swapWordsIfBigEndian;
using detail::nextLine;
using detail::splitBlanks;

uint64_t fileSize(std::FILE* file, const std::string& path) {
  const long size = (std::fseek(file, 0, SEEK_END) == 0) ? std::ftell(file) : -1L;
  if (size < 0 || std::fseek(file, 0, SEEK_SET) != 0) throw Error("cannot read " + path + ": " + std::strerror(errno));
  return static_cast<uint64_t>(size);
}

/// Reads the rest of an open file of @p bytes bytes as records of type T with one fread (the scans are ~2 MB;
/// speed matters when streaming a sequence).
template <typename T>
std::vector<T> readRecords(std::FILE* file, const std::string& path, uint64_t bytes) {
  std::vector<T> records;
  try {
    records.resize(bytes / sizeof(T));
  } catch (const std::bad_alloc&) {
    throw Error(path + ": " + std::to_string(bytes) + " bytes do not fit in memory");
  }
  if (!records.empty() && std::fread(records.data(), sizeof(T), records.size(), file) != records.size()) {
    throw Error("cannot read " + path + ": " + (std::ferror(file) ? std::strerror(errno) : "file shrank"));
  }
  if constexpr (sizeof(T) == 4) swapWordsIfBigEndian(records);
  return records;
}

/// A whole file of fixed-size records of 4-byte words: @p record_words words make one record; @p what describes
/// the record for the size error.
template <typename T>
std::vector<T> readWordFile(const std::string& path, size_t record_words, const char* what) {
  FilePtr file = detail::openForReading(path);
  const uint64_t bytes = fileSize(file.get(), path);
  const uint64_t record_bytes = record_words * sizeof(T);
  if (bytes % record_bytes != 0) {
    throw Error(path + ": size " + std::to_string(bytes) + " bytes is not a multiple of " +
                std::to_string(record_bytes) + " (" + what + ")");
  }
  return readRecords<T>(file.get(), path, bytes);
}

/// The labels of a scan of @p points points in @p format (auto: by the file size). @p scan names the scan in the
/// size error ("" when the caller gave only a count). The size is checked before anything is allocated.
std::vector<uint32_t> readLabelsOf(const std::string& path, uint64_t points, LabelFormat format,
                                   const std::string& scan) {
  FilePtr file = detail::openForReading(path);
  const uint64_t bytes = fileSize(file.get(), path);
  const bool is32 = bytes % 4 == 0 && bytes / 4 == points, is8 = bytes == points;  // no overflow of 4·points
  const bool bytewise = format == LabelFormat::kUint8 || (format == LabelFormat::kAuto && !is32);
  if (bytewise ? is8 : is32) {
    if (!bytewise) return readRecords<uint32_t>(file.get(), path, bytes);
    const std::vector<uint8_t> ids = readRecords<uint8_t>(file.get(), path, bytes);
    return std::vector<uint32_t>(ids.begin(), ids.end());
  }
  const std::string as32 = std::to_string(4 * points) + " (uint32 labels, 4 bytes a point)";
  const std::string as8 = std::to_string(points) + " (uint8 labels, 1 byte a point)";
  const std::string want = format == LabelFormat::kUint32  ? "not " + as32
                           : format == LabelFormat::kUint8 ? "not " + as8
                                                           : "neither " + as32 + " nor " + as8;
  throw Error("point/label count mismatch: " + (scan.empty() ? std::string("the scan") : scan) + " has " +
              std::to_string(points) + " points but " + path + " has " + std::to_string(bytes) + " bytes, " + want);
}

/// Parses 12 numbers (row-major 3×4 [R|t]) into a 4×4 matrix; @p where prefixes the error ("FILE:LINE").
Eigen::Matrix4d parseRowMajor3x4(const std::vector<std::string_view>& tokens, size_t first, const std::string& where) {
  const size_t count = tokens.size() - first;
  if (count != 12) throw Error(where + ": expected 12 numbers (row-major 3x4), found " + std::to_string(count));
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  for (Eigen::Index k = 0; k < 12; ++k) {
    const std::string_view token = tokens[first + static_cast<size_t>(k)];
    double& value = T(k / 4, k % 4);
    if (!detail::parseReal(token, value) || !std::isfinite(value)) {
      throw Error(where + ": " + quoteContent(token) + " is not a finite number");
    }
  }
  return T;
}

}  // namespace

std::vector<Eigen::Vector3f> readKittiBin(const std::string& path, std::vector<float>* intensity) {
  FilePtr file = detail::openForReading(path);
  const uint64_t bytes = fileSize(file.get(), path);
  constexpr uint64_t kRecord = 4 * sizeof(float);
  if (bytes % kRecord != 0) {
    throw Error(path + ": size " + std::to_string(bytes) + " bytes is not a multiple of " + std::to_string(kRecord) +
                " (x y z intensity float32)");
  }
  const size_t n = static_cast<size_t>(bytes / kRecord);
  std::vector<Eigen::Vector3f> points;
  try {
    points.resize(n);
    if (intensity) intensity->resize(n);
  } catch (const std::bad_alloc&) {
    throw Error(path + ": " + std::to_string(bytes) + " bytes do not fit in memory");
  }
  // Read through a fixed buffer rather than the whole file at once: a whole-file copy would add 16 bytes a point
  // to the 12 of the result at the peak (BENCHMARKS.md "Memory on big inputs").
  constexpr size_t kChunk = 1 << 16;  // records a read
  std::vector<float> raw(4 * std::min(n, kChunk));
  for (size_t first = 0; first < n; first += kChunk) {
    const size_t count = std::min(kChunk, n - first);
    if (std::fread(raw.data(), kRecord, count, file.get()) != count) {
      throw Error("cannot read " + path + ": " + (std::ferror(file.get()) ? std::strerror(errno) : "file shrank"));
    }
    swapWordsIfBigEndian(raw);
    for (size_t i = 0; i < count; ++i) points[first + i] = Eigen::Vector3f(raw[4 * i], raw[4 * i + 1], raw[4 * i + 2]);
    if (intensity) {
      for (size_t i = 0; i < count; ++i) (*intensity)[first + i] = raw[4 * i + 3];
    }
  }
  return points;
}

std::vector<uint32_t> readLabelFile(const std::string& path) {
  return readWordFile<uint32_t>(path, 1, "uint32 labels");
}

std::vector<uint32_t> readLabelFile(const std::string& path, size_t point_count, LabelFormat format) {
  return readLabelsOf(path, point_count, format, "");
}

std::vector<uint32_t> readLabelFileOf(const std::string& path, const std::string& scan_path, size_t point_count,
                                      LabelFormat format) {
  return readLabelsOf(path, point_count, format, scan_path);
}

LabeledCloud readLabeledScan(const std::string& bin_path, const std::string& label_path, LabelFormat format) {
  LabeledCloud cloud;
  cloud.points = readKittiBin(bin_path);
  cloud.labels = readLabelsOf(label_path, cloud.points.size(), format, bin_path);
  return cloud;
}

std::string defaultLabelPath(const std::string& bin_path) {
  const fs::path bin(bin_path);
  const fs::path name = fs::path(bin.stem()).concat(".label");
  // `dir/..` rather than dir.parent_path(), so that a bare "NAME.bin" run inside velodyne/ also finds ../labels.
  const fs::path dir = bin.has_parent_path() ? bin.parent_path() : fs::path(".");
  const fs::path semantic_kitti = (dir / ".." / "labels" / name).lexically_normal();
  std::error_code ec;
  if (fs::is_regular_file(semantic_kitti, ec)) return semantic_kitti.string();
  return fs::path(bin).replace_extension(".label").string();
}

std::vector<Eigen::Matrix4d> readKittiPoses(const std::string& path) {
  const std::string text = detail::readWholeFile(path);
  std::vector<Eigen::Matrix4d> poses;
  size_t pos = 0;
  size_t line_no = 0;
  size_t first_blank = 0;  // frame i is line i, so a blank line is only allowed if nothing follows it
  while (pos < text.size()) {
    ++line_no;
    const std::vector<std::string_view> tokens = splitBlanks(nextLine(text, pos));
    if (tokens.empty()) {
      if (first_blank == 0) first_blank = line_no;
      continue;
    }
    const std::string where = path + ":" + std::to_string(line_no);
    if (first_blank != 0) {
      throw Error(where + ": pose after blank line " + std::to_string(first_blank) + " (frame i must be line i)");
    }
    poses.push_back(parseRowMajor3x4(tokens, 0, where));
  }
  return poses;
}

Eigen::Matrix4d readKittiCalibTr(const std::string& path) {
  const std::string text = detail::readWholeFile(path);
  size_t pos = 0;
  size_t line_no = 0;
  size_t tr_line = 0;
  Eigen::Matrix4d Tr;
  while (pos < text.size()) {
    ++line_no;
    const std::vector<std::string_view> tokens = splitBlanks(nextLine(text, pos));
    if (tokens.empty() || tokens.front() != "Tr:") continue;
    // Two Tr lines leave the transform ambiguous (a merged or concatenated file): refuse rather than pick one.
    if (tr_line != 0) {
      throw Error(path + ":" + std::to_string(line_no) + ": a second Tr: line (line " + std::to_string(tr_line) +
                  " has one)");
    }
    Tr = parseRowMajor3x4(tokens, 1, path + ":" + std::to_string(line_no));
    tr_line = line_no;
  }
  if (tr_line == 0) {
    throw Error(path + ": no 'Tr:' line (the velodyne-to-cam0 transform of a KITTI odometry calib.txt)");
  }
  return Tr;
}

std::vector<Eigen::Matrix4d> lidarPoses(const std::vector<Eigen::Matrix4d>& cam_poses, const Eigen::Matrix4d& Tr) {
  // The full 4×4 inverse, not the rigid shortcut: KITTI's Tr is not exactly orthonormal, and the reference
  // relative poses in data/README.md were computed with inv(Tr).
  Eigen::Matrix4d Tr_inv;
  bool invertible = false;
  Tr.computeInverseWithCheck(Tr_inv, invertible);
  if (!invertible) throw Error("lidarPoses: the calibration Tr is not invertible");
  std::vector<Eigen::Matrix4d> out;
  out.reserve(cam_poses.size());
  for (const Eigen::Matrix4d& P : cam_poses) out.push_back(Tr_inv * P * Tr);
  return out;
}

}  // namespace sgtllc::io
