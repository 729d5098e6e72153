// PCD header: PCL's "The PCD (Point Cloud Data) file format" v0.7 (v0.6 = no VIEWPOINT line).
#include "pcd_header.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <optional>

#include "file_util.h"
#include "sgtllc/io/quote.h"
#include "sgtllc/types.h"

namespace sgtllc::io::detail {
namespace {

/// Values of one header keyword line, remembered with its line number for later cross-checks.
struct HeaderLine {
  std::vector<std::string_view> values;
  size_t line = 0;
};

[[noreturn]] void badHeader(const std::string& path, size_t line, const std::string& what) {
  throw Error(path + ":" + std::to_string(line) + ": malformed header line: " + what);
}

PcdData parseDataKind(std::string_view value, const std::string& path, size_t line) {
  if (value == "ascii") return PcdData::kAscii;
  if (value == "binary") return PcdData::kBinary;
  if (value == "binary_compressed") return PcdData::kBinaryCompressed;
  throw Error(path + ":" + std::to_string(line) + ": unsupported DATA type " + quoteContent(value) +
              " (expected ascii, binary or binary_compressed)");
}

size_t headerSize(const HeaderLine& entry, const std::string& path, const char* key) {
  size_t value = 0;
  if (entry.values.size() != 1 || !parseInteger(entry.values[0], value)) {
    badHeader(path, entry.line, std::string(key) + " needs one non-negative integer");
  }
  return value;
}

/// Builds the field table from FIELDS / SIZE / TYPE / COUNT (COUNT is optional and defaults to 1).
std::vector<PcdField> buildFields(const HeaderLine& names, const HeaderLine& sizes, const HeaderLine& types,
                                  const std::optional<HeaderLine>& counts, const std::string& path) {
  const size_t n = names.values.size();
  if (n == 0) badHeader(path, names.line, "FIELDS lists no field");
  auto checkLength = [&](const HeaderLine& entry, const char* key) {
    if (entry.values.size() != n) {
      badHeader(path, entry.line, std::string(key) + " has " + std::to_string(entry.values.size()) +
                                      " entries but FIELDS has " + std::to_string(n));
    }
  };
  checkLength(sizes, "SIZE");
  checkLength(types, "TYPE");
  if (counts) checkLength(*counts, "COUNT");

  std::vector<PcdField> fields(n);
  for (size_t i = 0; i < n; ++i) {
    PcdField& f = fields[i];
    f.name = std::string(names.values[i]);
    if (!parseInteger(sizes.values[i], f.size) || (f.size != 1 && f.size != 2 && f.size != 4 && f.size != 8)) {
      badHeader(path, sizes.line, "SIZE " + quoteContent(sizes.values[i]) + " is not 1, 2, 4 or 8");
    }
    const std::string_view type = types.values[i];
    if (type != "I" && type != "U" && type != "F") {
      badHeader(path, types.line, "TYPE " + quoteContent(type) + " is not I, U or F");
    }
    f.type = type[0];
    // A bound far above any real field (PCL's largest are 308-float histograms) keeps SIZE × COUNT and the sum
    // over fields from overflowing into wrapped offsets.
    constexpr size_t kMaxCount = size_t{1} << 20;
    if (counts && (!parseInteger(counts->values[i], f.count) || f.count == 0 || f.count > kMaxCount)) {
      badHeader(path, counts->line,
                "COUNT " + quoteContent(counts->values[i]) + " is not an integer in 1.." + std::to_string(kMaxCount));
    }
  }
  return fields;
}

void layOut(PcdHeader& h) {
  for (PcdField& f : h.fields) {
    f.offset = h.point_bytes;
    f.token = h.point_tokens;
    h.point_bytes += f.bytes();
    h.point_tokens += f.count;
  }
}

std::string fieldList(const PcdHeader& h) {
  std::string names;
  for (const PcdField& f : h.fields) {
    if (!names.empty()) names += ' ';
    names += escapeContent(f.name);
  }
  return names;
}

const PcdField& findField(const PcdHeader& h, const std::string& name, const std::string& path) {
  for (const PcdField& f : h.fields) {
    if (f.name == name) {
      if (f.count != 1) {
        throw Error(path + ": field " + quoteContent(name) + " has COUNT " + std::to_string(f.count) + "; expected 1");
      }
      return f;
    }
  }
  throw Error(path + ": no field " + quoteContent(name) + " (fields: " + fieldList(h) + ")");
}

}  // namespace

PcdHeader parsePcdHeader(std::string_view text, const std::string& path) {
  std::optional<HeaderLine> fields, sizes, types, counts, width, height, points;
  std::optional<HeaderLine>* slots[] = {&fields, &sizes, &types, &counts, &width, &height, &points};
  const char* keys[] = {"FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "POINTS"};
  PcdHeader h;
  size_t pos = 0;
  size_t line_no = 0;
  bool have_data = false;
  while (!have_data && pos < text.size()) {
    ++line_no;
    const std::vector<std::string_view> tokens = splitBlanks(nextLine(text, pos));
    if (tokens.empty() || tokens[0].front() == '#') continue;
    const std::string_view key = tokens[0];
    const HeaderLine entry{{tokens.begin() + 1, tokens.end()}, line_no};
    if (key == "VERSION" || key == "VIEWPOINT") continue;  // neither changes how the data is laid out
    if (key == "DATA") {
      if (entry.values.size() != 1) badHeader(path, line_no, "DATA needs one value");
      h.data = parseDataKind(entry.values[0], path, line_no);
      h.data_offset = pos;
      h.data_line = line_no;
      have_data = true;
      continue;
    }
    const auto* slot = std::find(std::begin(keys), std::end(keys), key);
    if (slot == std::end(keys)) badHeader(path, line_no, "unknown keyword " + quoteContent(key));
    *slots[slot - std::begin(keys)] = entry;
  }
  if (!have_data) throw Error(path + ": PCD header has no DATA line");
  for (size_t k = 0; k < std::size(keys); ++k) {
    const bool optional = keys[k] == std::string_view("COUNT");  // PCL defaults COUNT to 1 when it is absent
    if (!optional && !*slots[k]) throw Error(path + ": PCD header has no " + keys[k] + " line");
  }
  h.fields = buildFields(*fields, *sizes, *types, counts, path);
  layOut(h);
  const size_t w = headerSize(*width, path, "WIDTH");
  const size_t ht = headerSize(*height, path, "HEIGHT");
  h.points = headerSize(*points, path, "POINTS");
  if (ht != 0 && w > std::numeric_limits<size_t>::max() / ht) badHeader(path, height->line, "WIDTH x HEIGHT overflows");
  if (w * ht != h.points) {
    throw Error(path + ": WIDTH x HEIGHT = " + std::to_string(w) + " x " + std::to_string(ht) + " = " +
                std::to_string(w * ht) + " but POINTS = " + std::to_string(h.points));
  }
  return h;
}

std::string typeName(const PcdField& f) { return std::string(1, f.type) + std::to_string(f.size); }

XyzLabelFields resolveFields(const PcdHeader& h, const std::string& label_field, const std::string& path) {
  XyzLabelFields w{&findField(h, "x", path), &findField(h, "y", path), &findField(h, "z", path),
                   label_field.empty() ? nullptr : &findField(h, label_field, path)};
  for (const PcdField* f : {w.x, w.y, w.z}) {
    if (f->type != 'F' || (f->size != 4 && f->size != 8)) {
      throw Error(path + ": field " + quoteContent(f->name) + " is " + typeName(*f) + "; expected F4 or F8");
    }
  }
  if (w.label && w.label->type == 'F' && w.label->size < 4) {
    throw Error(path + ": label field " + quoteContent(label_field) + " is " + typeName(*w.label) + "; expected F4 or F8");
  }
  return w;
}

}  // namespace sgtllc::io::detail
