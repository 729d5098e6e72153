// PLY reader (Turk's PLY format / Paul Bourke's "PLY - Polygon File Format"): the vertex element's x, y, z and an
// optional label, for scans saved by PCL, Open3D or CloudCompare (README "Data formats").
#include "sgtllc/io/ply_read.h"

#include <algorithm>
#include <cstring>
#include <optional>
#include <string_view>

#include "file_util.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::io {
namespace {

enum class PlyFormat { kAscii, kLittleEndian, kBigEndian };

struct Scalar {
  char kind = '?';  ///< 'I' signed, 'U' unsigned, 'F' floating point
  size_t size = 0;  ///< bytes
};

struct PlyProperty {
  std::string name;
  Scalar value;
  bool list = false;
  Scalar count;  ///< the list's length type (lists only)
};

struct PlyElement {
  std::string name;
  size_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  size_t data_offset = 0;  ///< first byte after end_header
  size_t data_line = 0;    ///< line number of end_header
};

std::optional<Scalar> scalarType(std::string_view name) {
  static constexpr struct {
    const char* name;
    char kind;
    size_t size;
  } kTypes[] = {{"char", 'I', 1},  {"int8", 'I', 1},   {"uchar", 'U', 1},   {"uint8", 'U', 1},
                {"short", 'I', 2}, {"int16", 'I', 2},  {"ushort", 'U', 2},  {"uint16", 'U', 2},
                {"int", 'I', 4},   {"int32", 'I', 4},  {"uint", 'U', 4},    {"uint32", 'U', 4},
                {"float", 'F', 4}, {"float32", 'F', 4}, {"double", 'F', 8}, {"float64", 'F', 8}};
  for (const auto& t : kTypes) {
    if (name == t.name) return Scalar{t.kind, t.size};
  }
  return std::nullopt;
}

PlyHeader parseHeader(std::string_view text, const std::string& path) {
  size_t pos = 0;
  size_t line_no = 1;
  if (detail::splitBlanks(detail::nextLine(text, pos)) != std::vector<std::string_view>{"ply"}) {
    throw Error(path + ": not a PLY file (the first line is not 'ply')");
  }
  PlyHeader h;
  bool have_format = false;
  for (;;) {
    if (pos >= text.size()) throw Error(path + ": no end_header line");
    const std::string_view line = detail::nextLine(text, pos);
    ++line_no;
    const std::vector<std::string_view> t = detail::splitBlanks(line);
    auto fail = [&](const std::string& why) {
      throw Error(path + ":" + std::to_string(line_no) + ": malformed header line: " + quoteContent(line) +
                  (why.empty() ? "" : " (" + why + ")"));
    };
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") break;
    if (t[0] == "format") {
      if (t.size() != 3) fail("expected: format ascii|binary_little_endian|binary_big_endian 1.0");
      if (t[1] == "ascii") {
        h.format = PlyFormat::kAscii;
      } else if (t[1] == "binary_little_endian") {
        h.format = PlyFormat::kLittleEndian;
      } else if (t[1] == "binary_big_endian") {
        h.format = PlyFormat::kBigEndian;
      } else {
        fail("unknown format");
      }
      have_format = true;
    } else if (t[0] == "element") {
      PlyElement e;
      if (t.size() != 3 || !detail::parseInteger(t[2], e.count)) fail("expected: element NAME COUNT");
      e.name = std::string(t[1]);
      h.elements.push_back(std::move(e));
    } else if (t[0] == "property") {
      if (h.elements.empty()) fail("a property before any element");
      PlyProperty p;
      const bool list = t.size() == 5 && t[1] == "list";
      if (!list && t.size() != 3) fail("expected: property TYPE NAME or property list COUNT_TYPE TYPE NAME");
      const std::optional<Scalar> value = scalarType(t[list ? 3 : 1]);
      const std::optional<Scalar> count = list ? scalarType(t[2]) : Scalar{'U', 1};
      if (!value || !count || count->kind == 'F') fail("unknown type");
      p.name = std::string(t.back());
      p.value = *value;
      p.list = list;
      p.count = *count;
      h.elements.back().properties.push_back(std::move(p));
    } else {
      fail("");
    }
  }
  if (!have_format) throw Error(path + ": no format line in the PLY header");
  h.data_offset = pos;
  h.data_line = line_no;
  return h;
}

const PlyElement& vertexElement(const PlyHeader& h, const std::string& path) {
  for (const PlyElement& e : h.elements) {
    if (e.name == "vertex") return e;
  }
  throw Error(path + ": no vertex element (a point cloud's points are its vertices)");
}

/// Index of property @p name of @p e, which must be a scalar (of a floating-point type if @p coordinate).
size_t findProperty(const PlyElement& e, const std::string& name, bool coordinate, const std::string& path) {
  for (size_t k = 0; k < e.properties.size(); ++k) {
    const PlyProperty& p = e.properties[k];
    if (p.name != name) continue;
    if (p.list) throw Error(path + ": property '" + name + "' is a list, not one value a point");
    if (coordinate && p.value.kind != 'F') throw Error(path + ": property '" + name + "' must be float or double");
    return k;
  }
  std::string names;
  for (const PlyProperty& p : e.properties) names += (names.empty() ? "" : " ") + p.name;
  throw Error(path + ": no property '" + name + "' in element vertex (properties: " + escapeContent(names, kNameBytes) +
              ")");
}

/// A binary value of type @p s at @p p, in the file's byte order.
double binaryValue(const char* p, Scalar s, bool big_endian) {
  char b[8];
  std::memcpy(b, p, s.size);
  if (big_endian == detail::kHostLittleEndian) std::reverse(b, b + s.size);
  auto as = [&b](auto v) {
    std::memcpy(&v, b, sizeof(v));
    return static_cast<double>(v);
  };
  if (s.kind == 'F') return s.size == 4 ? as(float{}) : as(double{});
  switch (s.size) {
    case 1: return s.kind == 'I' ? as(int8_t{}) : as(uint8_t{});
    case 2: return s.kind == 'I' ? as(int16_t{}) : as(uint16_t{});
    default: return s.kind == 'I' ? as(int32_t{}) : as(uint32_t{});
  }
}

/// The wanted properties of every vertex (x, y, z and, if @p label, the label), as doubles, through @p take.
struct Wanted {
  size_t index[4];
  int n;
};

template <typename Take>
void readBinary(std::string_view bytes, const PlyHeader& h, const Wanted& w, const std::string& path, Take take) {
  const bool big = h.format == PlyFormat::kBigEndian;
  size_t pos = h.data_offset;
  auto need = [&](size_t n, const std::string& element) {
    if (bytes.size() - pos < n) throw Error(path + ": truncated binary data in element " + element);
  };
  for (const PlyElement& e : h.elements) {
    const bool vertex = e.name == "vertex";
    if (e.properties.empty()) continue;  // no bytes, however many entries it claims
    for (size_t i = 0; i < e.count; ++i) {
      double v[4] = {0, 0, 0, 0};
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        size_t n = 1;
        if (p.list) {
          need(p.count.size, e.name);
          const double length = binaryValue(bytes.data() + pos, p.count, big);
          if (length < 0) throw Error(path + ": negative list length in element " + escapeContent(e.name));
          n = static_cast<size_t>(length);
          pos += p.count.size;
        }
        need(n * p.value.size, e.name);
        for (int j = 0; vertex && j < w.n; ++j) {
          if (w.index[j] == k) v[j] = binaryValue(bytes.data() + pos, p.value, big);
        }
        pos += n * p.value.size;
      }
      if (vertex) take(v);
    }
    if (vertex) return;  // what follows the vertices is not needed
  }
}

template <typename Take>
void readAscii(std::string_view bytes, const PlyHeader& h, const Wanted& w, const std::string& path, Take take) {
  size_t pos = h.data_offset;
  size_t line_no = h.data_line;
  for (const PlyElement& e : h.elements) {
    const bool vertex = e.name == "vertex";
    for (size_t i = 0; i < e.count;) {
      if (pos >= bytes.size()) {
        throw Error(path + ": truncated ascii data: element " + escapeContent(e.name) + " has " +
                    std::to_string(e.count) + " entries, found " + std::to_string(i));
      }
      ++line_no;
      const std::vector<std::string_view> t = detail::splitBlanks(detail::nextLine(bytes, pos));
      if (t.empty()) continue;
      ++i;
      if (!vertex) continue;  // one line an entry, whatever it holds
      const std::string where = path + ":" + std::to_string(line_no);
      double v[4] = {0, 0, 0, 0};
      size_t token = 0;
      for (size_t k = 0; k < e.properties.size(); ++k) {
        size_t n = 1;
        if (e.properties[k].list && (token >= t.size() || !detail::parseInteger(t[token++], n))) {
          throw Error(where + ": list " + quoteContent(e.properties[k].name) + " has no valid length");
        }
        if (t.size() - std::min(token, t.size()) < n) throw Error(where + ": too few values for a vertex");
        for (int j = 0; j < w.n; ++j) {
          if (w.index[j] == k && !detail::parseReal(t[token], v[j])) {
            throw Error(where + ": property " + quoteContent(e.properties[k].name) + ": " + quoteContent(t[token]) +
                        " is not a number");
          }
        }
        token += n;
      }
      if (token != t.size()) throw Error(where + ": more values than the vertex's properties");
      take(v);
    }
    if (vertex) return;
  }
}

LabeledCloud readPlyFile(const std::string& path, const std::string& label_field) {
  const std::string bytes = detail::readWholeFile(path);
  const PlyHeader h = parseHeader(bytes, path);
  const PlyElement& vertex = vertexElement(h, path);
  Wanted w{{findProperty(vertex, "x", true, path), findProperty(vertex, "y", true, path),
            findProperty(vertex, "z", true, path), 0},
           3};
  if (!label_field.empty()) w.index[w.n++] = findProperty(vertex, label_field, false, path);
  LabeledCloud cloud;
  const size_t reserve = std::min(vertex.count, bytes.size());  // a lying count must not allocate
  cloud.points.reserve(reserve);
  if (w.n == 4) cloud.labels.reserve(reserve);
  auto take = [&](const double* v) {
    if (w.n == 4) {
      const std::optional<uint32_t> label = detail::labelFromReal(v[3]);
      if (!label) {
        throw Error(path + ": vertex " + std::to_string(cloud.points.size()) + ": label " + std::to_string(v[3]) +
                    " is not a valid uint32 id");
      }
      cloud.labels.push_back(*label);
    }
    cloud.points.emplace_back(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
  };
  if (h.format == PlyFormat::kAscii) {
    readAscii(bytes, h, w, path, take);
  } else {
    readBinary(bytes, h, w, path, take);
  }
  return cloud;
}

}  // namespace

LabeledCloud readPly(const std::string& path, const std::string& label_field) {
  if (label_field.empty()) {
    throw Error(path + ": no label property name given (readPlyPoints reads a PLY without labels)");
  }
  return readPlyFile(path, label_field);
}

std::vector<Eigen::Vector3f> readPlyPoints(const std::string& path) { return readPlyFile(path, "").points; }

std::vector<std::string> plyVertexProperties(const std::string& path) {
  const std::string bytes = detail::readWholeFile(path);
  std::vector<std::string> names;
  const PlyHeader header = parseHeader(bytes, path);
  for (const PlyProperty& p : vertexElement(header, path).properties) names.push_back(p.name);
  return names;
}

}  // namespace sgtllc::io
