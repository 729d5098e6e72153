// Shared by the PCD test suites (test_io_pcd*.cpp): a PCD writer built byte by byte from the PCD v0.7 spec (header
// lines, ascii rows, binary records, binary_compressed = two uint32 sizes + LZF of the fields stored one after
// another), independent of the library's reader, and random clouds to write with it.
#pragma once

#include <cmath>
#include <cstring>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <liblzf/lzf.h>

#include "test_io_support.h"

namespace sgtllc::test {

// ------------------------------------------------------------------------------------------------------------------
// A minimal PCD writer for the tests (independent of the library's reader).

struct TestField {
  std::string name;
  char type;  // I, U, F
  int size;   // bytes
  int count;
};

inline void PrintTo(const TestField& f, std::ostream* os) { *os << f.name << ':' << f.type << f.size << 'x' << f.count; }

/// A cloud as plain numbers: rows[i] holds every element of point i, fields in order, COUNT elements each.
struct TestCloud {
  std::vector<TestField> fields;
  std::vector<std::vector<double>> rows;
  size_t width = 0, height = 1;  // width 0 = number of rows
};

inline std::string header(const TestCloud& c, const std::string& data, const std::string& version = "0.7",
                   bool with_count = true) {
  std::ostringstream h;
  h << "# .PCD v" << version << " - Point Cloud Data file format\nVERSION " << version << "\nFIELDS";
  for (const auto& f : c.fields) h << ' ' << f.name;
  h << "\nSIZE";
  for (const auto& f : c.fields) h << ' ' << f.size;
  h << "\nTYPE";
  for (const auto& f : c.fields) h << ' ' << f.type;
  if (with_count) {
    h << "\nCOUNT";
    for (const auto& f : c.fields) h << ' ' << f.count;
  }
  h << "\nWIDTH " << (c.width ? c.width : c.rows.size()) << "\nHEIGHT " << c.height << "\n";
  if (version == "0.7") h << "VIEWPOINT 0 0 0 1 0 0 0\n";
  h << "POINTS " << c.rows.size() << "\nDATA " << data << "\n";
  return h.str();
}

template <typename T>
inline void put(std::string& out, double v) {
  const T t = static_cast<T>(v);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &t, sizeof(T));  // the test host is little-endian, as PCL files are
  out.append(bytes, sizeof(T));
}

inline void putScalar(std::string& out, const TestField& f, double v) {
  if (f.type == 'F') return f.size == 4 ? put<float>(out, v) : put<double>(out, v);
  const bool s = f.type == 'I';
  switch (f.size) {
    case 1: return s ? put<int8_t>(out, v) : put<uint8_t>(out, v);
    case 2: return s ? put<int16_t>(out, v) : put<uint16_t>(out, v);
    case 4: return s ? put<int32_t>(out, v) : put<uint32_t>(out, v);
    default: return s ? put<int64_t>(out, v) : put<uint64_t>(out, v);
  }
}

/// First element of field @p k within a row.
inline size_t elementIndex(const TestCloud& c, size_t k) {
  size_t e = 0;
  for (size_t j = 0; j < k; ++j) e += static_cast<size_t>(c.fields[j].count);
  return e;
}

inline std::string asciiPcd(const TestCloud& c) {
  std::ostringstream out;
  out << header(c, "ascii") << std::setprecision(17);
  for (const auto& row : c.rows) {
    for (size_t e = 0; e < row.size(); ++e) out << (e ? " " : "") << row[e];
    out << "\n";
  }
  return out.str();
}

inline std::string binaryPcd(const TestCloud& c) {
  std::string out = header(c, "binary");
  for (const auto& row : c.rows) {
    for (size_t k = 0; k < c.fields.size(); ++k) {
      for (int j = 0; j < c.fields[k].count; ++j) putScalar(out, c.fields[k], row[elementIndex(c, k) + j]);
    }
  }
  return out;
}

inline std::string compressedPcd(const TestCloud& c) {
  std::string soa;  // field by field: every point's elements of field 0, then of field 1, ...
  for (size_t k = 0; k < c.fields.size(); ++k) {
    for (const auto& row : c.rows) {
      for (int j = 0; j < c.fields[k].count; ++j) putScalar(soa, c.fields[k], row[elementIndex(c, k) + j]);
    }
  }
  std::string packed(soa.size() + soa.size() / 16 + 64, '\0');
  const unsigned n = soa.empty() ? 0 : lzf_compress(soa.data(), static_cast<unsigned>(soa.size()), packed.data(),
                                                    static_cast<unsigned>(packed.size()));
  EXPECT_TRUE(soa.empty() || n > 0);
  std::string out = header(c, "binary_compressed");
  put<uint32_t>(out, n);
  put<uint32_t>(out, static_cast<double>(soa.size()));
  out.append(packed.data(), n);
  return out;
}

inline std::string encode(const TestCloud& c, const std::string& data) {
  if (data == "ascii") return asciiPcd(c);
  if (data == "binary") return binaryPcd(c);
  return compressedPcd(c);
}


// ------------------------------------------------------------------------------------------------------------------

class PcdIo : public sgtllc::test::TempDirTest {};

/// Fields in a deliberately mixed order, with an extra scalar (intensity), a 2-count field and packed rgb, so the
/// reader must get every offset right. The label field's type varies.
inline TestCloud randomCloud(const TestField& label, size_t n, uint32_t seed) {
  TestCloud c;
  c.fields = {{"intensity", 'F', 4, 1}, {"x", 'F', 4, 1},     {"y", 'F', 4, 1}, {"normal_xy", 'F', 4, 2},
              {"z", 'F', 4, 1},         label,                {"rgb", 'U', 4, 1}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coord(-80.f, 80.f);
  std::uniform_int_distribution<int> id(0, 120);
  for (size_t i = 0; i < n; ++i) {
    double l = id(rng);
    if (label.type == 'F') l += (i % 2 ? 0.4 : -0.4);  // floats are rounded to the nearest id
    if (label.type == 'I' && i % 7 == 3) l = -1;        // a common "unlabelled" convention
    c.rows.push_back({coord(rng) / 80.f, coord(rng), coord(rng), 0.25, -0.5, coord(rng), l, double(rng() & 0xFFFFFF)});
  }
  return c;
}

inline uint32_t expectedLabel(double v) { return static_cast<uint32_t>(static_cast<int64_t>(std::llround(v))); }

}  // namespace sgtllc::test
