// PCD reader/writer. Format: PCL's "The PCD (Point Cloud Data) file format" v0.7 (v0.6 = no VIEWPOINT line).
// The header is parsed in pcd_header.cpp; this file decodes the three kinds of data section.
#include "sgtllc/io/pcd.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>

#include <liblzf/lzf.h>

#include "file_util.h"
#include "pcd_header.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::io {
namespace {

using detail::PcdData;
using detail::PcdField;
using detail::PcdHeader;
using detail::XyzLabelFields;
using detail::labelFromReal;
using detail::typeName;

template <typename T>
T load(const char* p) {
  T value;
  if constexpr (detail::kHostLittleEndian || sizeof(T) == 1) {
    std::memcpy(&value, p, sizeof(T));
  } else {
    char swapped[sizeof(T)];
    for (size_t k = 0; k < sizeof(T); ++k) swapped[k] = p[sizeof(T) - 1 - k];
    std::memcpy(&value, swapped, sizeof(T));
  }
  return value;
}

std::optional<uint32_t> labelFromBytes(const char* p, const PcdField& f) {
  if (f.type == 'F') return labelFromReal(f.size == 4 ? load<float>(p) : load<double>(p));
  const bool is_signed = f.type == 'I';
  switch (f.size) {
    case 1: return is_signed ? static_cast<uint32_t>(load<int8_t>(p)) : load<uint8_t>(p);
    case 2: return is_signed ? static_cast<uint32_t>(load<int16_t>(p)) : load<uint16_t>(p);
    case 4: return is_signed ? static_cast<uint32_t>(load<int32_t>(p)) : load<uint32_t>(p);
    default: {  // 8 bytes: keep only values that fit the same range as the smaller types
      const uint64_t v = load<uint64_t>(p);
      if (is_signed) return labelFromReal(static_cast<double>(static_cast<int64_t>(v)));
      return v > 0xFFFFFFFFull ? std::nullopt : std::optional<uint32_t>(static_cast<uint32_t>(v));
    }
  }
}

float coordFromBytes(const char* p, const PcdField& f) {
  return f.size == 4 ? load<float>(p) : static_cast<float>(load<double>(p));
}

[[noreturn]] void badLabel(const std::string& path, size_t point, const std::string& value) {
  throw Error(path + ": point " + std::to_string(point) + ": label " + value + " is not a valid uint32 id");
}

// ---------------------------------------------------------------------------------------------------------------
// Data sections

/// Where one field's values lie in a decoded binary block: value i is at base + offset + i * stride.
struct Column {
  size_t offset;
  size_t stride;
};

/// Decodes x, y, z and label from a binary block in either layout. @p column maps a field to its Column.
template <typename ColumnOf>
LabeledCloud decodeBinary(const char* data, const PcdHeader& h, const XyzLabelFields& w, ColumnOf column,
                          const std::string& path) {
  LabeledCloud cloud;
  cloud.points.resize(h.points);
  const Column cx = column(*w.x), cy = column(*w.y), cz = column(*w.z);
  for (size_t i = 0; i < h.points; ++i) {
    cloud.points[i] = Eigen::Vector3f(coordFromBytes(data + cx.offset + i * cx.stride, *w.x),
                                      coordFromBytes(data + cy.offset + i * cy.stride, *w.y),
                                      coordFromBytes(data + cz.offset + i * cz.stride, *w.z));
  }
  if (!w.label) return cloud;  // points only (readPcdPoints)
  cloud.labels.resize(h.points);
  const Column cl = column(*w.label);
  for (size_t i = 0; i < h.points; ++i) {
    const std::optional<uint32_t> label = labelFromBytes(data + cl.offset + i * cl.stride, *w.label);
    if (!label) badLabel(path, i, "(" + typeName(*w.label) + ")");
    cloud.labels[i] = *label;
  }
  return cloud;
}

size_t dataBytes(const PcdHeader& h, const std::string& path) {
  if (h.points > std::numeric_limits<size_t>::max() / h.point_bytes) throw Error(path + ": POINTS is too large");
  return h.points * h.point_bytes;
}

[[noreturn]] void truncated(const std::string& path, const char* kind, size_t need, size_t have, size_t points) {
  throw Error(path + ": truncated " + kind + " data: " + std::to_string(points) + " points need " +
              std::to_string(need) + " bytes, found " + std::to_string(have));
}

/// DATA binary: records stored point by point (array of structures).
LabeledCloud readBinary(std::string_view bytes, const PcdHeader& h, const XyzLabelFields& w, const std::string& path) {
  const size_t need = dataBytes(h, path);
  const size_t have = bytes.size() - h.data_offset;
  if (have < need) truncated(path, "binary", need, have, h.points);
  auto aos = [&h](const PcdField& f) { return Column{f.offset, h.point_bytes}; };
  return decodeBinary(bytes.data() + h.data_offset, h, w, aos, path);
}

/// LZF's largest expansion: a 3-byte back reference copies at most 264 bytes (liblzf lzf_d.c), so a block of
/// P compressed bytes never unpacks to more than 88 P. Checked before allocating, so a header that claims gigabytes
/// over a few bytes of data fails at once instead of reserving the memory.
constexpr uint64_t kLzfMaxExpansion = 88;

/// DATA binary_compressed: uint32 compressed size, uint32 uncompressed size, then LZF data that decompresses to
/// the fields stored one after another (structure of arrays: all x, then all y, …).
LabeledCloud readCompressed(std::string_view bytes, const PcdHeader& h, const XyzLabelFields& w,
                            const std::string& path) {
  const size_t have = bytes.size() - h.data_offset;
  if (have < 8) truncated(path, "binary_compressed", 8, have, h.points);
  const char* p = bytes.data() + h.data_offset;
  const uint32_t packed = load<uint32_t>(p);
  const uint32_t unpacked = load<uint32_t>(p + 4);
  // Every size is checked against the file and against each other before anything is allocated.
  if (have - 8 < packed) truncated(path, "binary_compressed", size_t{8} + packed, have, h.points);
  const size_t need = dataBytes(h, path);
  if (unpacked != need) {
    throw Error(path + ": binary_compressed block unpacks to " + std::to_string(unpacked) + " bytes but " +
                std::to_string(h.points) + " points of " + std::to_string(h.point_bytes) + " bytes need " +
                std::to_string(need));
  }
  if (unpacked > kLzfMaxExpansion * packed) {
    throw Error(path + ": binary_compressed block claims " + std::to_string(unpacked) + " bytes from " +
                std::to_string(packed) + " compressed bytes (LZF expands at most " +
                std::to_string(kLzfMaxExpansion) + " times): POINTS " + std::to_string(h.points) +
                " does not match the data");
  }
  // Not zero-filled: LZF writes every byte it reports, and a short result is an error.
  std::unique_ptr<char[]> soa(new char[std::max<size_t>(need, 1)]);
  if (need > 0 && lzf_decompress(p + 8, packed, soa.get(), unpacked) != unpacked) {
    throw Error(path + ": binary_compressed data is corrupt (LZF decompression failed)");
  }
  auto columns = [&h](const PcdField& f) { return Column{h.points * f.offset, f.bytes()}; };
  return decodeBinary(soa.get(), h, w, columns, path);
}

/// DATA ascii: one point per line, values separated by blanks; blank lines are ignored.
LabeledCloud readAscii(std::string_view bytes, const PcdHeader& h, const XyzLabelFields& w, const std::string& path) {
  // Each point takes at least two bytes per value (a digit and a blank or newline; the last newline may be
  // missing), so a POINTS the data section cannot hold fails before reading.
  const size_t have = bytes.size() - h.data_offset;
  if (h.points > 0 && h.point_tokens > 0 && (have + 1) / (2 * h.point_tokens) < h.points) {
    throw Error(path + ": POINTS " + std::to_string(h.points) + " cannot fit in the " + std::to_string(have) +
                " bytes of ascii data (" + std::to_string(h.point_tokens) + " values per point)");
  }
  LabeledCloud cloud;
  const size_t reserve = std::min(h.points, have);  // a lying POINTS must not allocate
  cloud.points.reserve(reserve);
  if (w.label) cloud.labels.reserve(reserve);
  size_t pos = h.data_offset;
  size_t line_no = h.data_line;
  while (pos < bytes.size()) {
    ++line_no;
    const std::vector<std::string_view> tokens = detail::splitBlanks(detail::nextLine(bytes, pos));
    if (tokens.empty()) continue;
    const std::string where = path + ":" + std::to_string(line_no);
    if (cloud.points.size() == h.points) throw Error(where + ": more points than POINTS " + std::to_string(h.points));
    if (tokens.size() != h.point_tokens) {
      throw Error(where + ": expected " + std::to_string(h.point_tokens) + " values, found " +
                  std::to_string(tokens.size()));
    }
    double v[4];
    const PcdField* fs[4] = {w.x, w.y, w.z, w.label};
    const int fields = w.label ? 4 : 3;  // points only (readPcdPoints): no label
    for (int k = 0; k < fields; ++k) {
      if (!detail::parseReal(tokens[fs[k]->token], v[k])) {
        throw Error(where + ": field " + quoteContent(fs[k]->name) + ": " + quoteContent(tokens[fs[k]->token]) +
                    " is not a number");
      }
    }
    if (w.label) {
      const std::optional<uint32_t> label = labelFromReal(v[3]);
      if (!label) badLabel(path, cloud.points.size(), escapeContent(tokens[w.label->token]));
      cloud.labels.push_back(*label);
    }
    cloud.points.emplace_back(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
  }
  if (cloud.points.size() != h.points) {
    throw Error(path + ": truncated ascii data: POINTS is " + std::to_string(h.points) + " but found " +
                std::to_string(cloud.points.size()) + " points");
  }
  return cloud;
}

}  // namespace

namespace {

/// Reads a PCD file; an empty @p label_field reads the points only (labels left empty).
LabeledCloud readPcdFile(const std::string& path, const std::string& label_field) {
  const std::string bytes = detail::readWholeFile(path);
  const PcdHeader header = detail::parsePcdHeader(bytes, path);
  const XyzLabelFields wanted = detail::resolveFields(header, label_field, path);
  switch (header.data) {
    case PcdData::kAscii: return readAscii(bytes, header, wanted, path);
    case PcdData::kBinary: return readBinary(bytes, header, wanted, path);
    case PcdData::kBinaryCompressed: return readCompressed(bytes, header, wanted, path);
  }
  throw Error(path + ": unsupported DATA type");  // unreachable: parsePcdHeader rejects the rest
}

}  // namespace

LabeledCloud readPcd(const std::string& path, const std::string& label_field) {
  if (label_field.empty()) throw Error(path + ": no label field name given (readPcdPoints reads a PCD without labels)");
  return readPcdFile(path, label_field);
}

std::vector<Eigen::Vector3f> readPcdPoints(const std::string& path) { return readPcdFile(path, "").points; }

std::vector<std::string> pcdFieldNames(const std::string& path) {
  std::vector<std::string> names;
  const PcdHeader header = detail::parsePcdHeader(detail::readWholeFile(path), path);
  for (const PcdField& f : header.fields) names.push_back(f.name);
  return names;
}

void writeNodesPcd(const std::string& path, const std::vector<Node>& nodes, int num_classes, Overwrite overwrite) {
  detail::checkNodeLabels(path, nodes, num_classes);
  const std::string n = std::to_string(nodes.size());
  std::string out =
      "# .PCD v0.7 - Point Cloud Data file format\n"
      "VERSION 0.7\n"
      "FIELDS x y z label\n"
      "SIZE 4 4 4 4\n"
      "TYPE F F F U\n"
      "COUNT 1 1 1 1\n"
      "WIDTH " + n + "\n"
      "HEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\n"
      "POINTS " + n + "\n"
      "DATA ascii\n";
  for (const Node& node : nodes) {
    for (int k = 0; k < 3; ++k) {
      detail::appendShortest(out, static_cast<float>(node.centre[k]));  // F4 because PCL's PointXYZL stores floats
      out += ' ';
    }
    out += std::to_string(node.label) + "\n";
  }
  writeFileAtomically(path, out, overwrite);
}

}  // namespace sgtllc::io
