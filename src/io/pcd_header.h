// PCD header parsing (PCL's "The PCD (Point Cloud Data) file format" v0.7; v0.6 = no VIEWPOINT line) and the
// resolution of the fields readPcd needs. Private to sgtllc_io.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sgtllc::io::detail {

enum class PcdData { kAscii, kBinary, kBinaryCompressed };

struct PcdField {
  std::string name;
  size_t size = 0;    ///< bytes per element (SIZE)
  char type = '?';    ///< 'I', 'U' or 'F' (TYPE)
  size_t count = 1;   ///< elements per point (COUNT)
  size_t offset = 0;  ///< bytes from the start of a point record
  size_t token = 0;   ///< index of its first value on an ascii line
  size_t bytes() const { return size * count; }
};

struct PcdHeader {
  std::vector<PcdField> fields;
  size_t points = 0;
  size_t point_bytes = 0;   ///< sum of SIZE × COUNT
  size_t point_tokens = 0;  ///< sum of COUNT (values per ascii line)
  PcdData data = PcdData::kAscii;
  size_t data_offset = 0;   ///< first byte after the DATA line
  size_t data_line = 0;     ///< line number of the DATA line
};

/// The fields readPcd needs, resolved against the header (pointers into PcdHeader::fields).
struct XyzLabelFields {
  const PcdField* x;
  const PcdField* y;
  const PcdField* z;
  const PcdField* label;  ///< null when only the points are read
};

/// Parses the header at the start of @p text, up to and including the DATA line. Throws sgtllc::Error naming
/// @p path (and the line) for a malformed or missing keyword line, an unsupported DATA kind, or WIDTH × HEIGHT ≠
/// POINTS.
PcdHeader parsePcdHeader(std::string_view text, const std::string& path);

/// Finds x, y, z (F4 or F8) and @p label_field (any type but F1/F2; none when empty: label null), each with COUNT 1;
/// throws naming @p path.
XyzLabelFields resolveFields(const PcdHeader& h, const std::string& label_field, const std::string& path);

/// "F4", "U2", …
std::string typeName(const PcdField& f);

}  // namespace sgtllc::io::detail
