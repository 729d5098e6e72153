// RFC 4180 fields (csv.h): the one writer and reader of quoted CSV fields.
#include "sgtllc/io/csv.h"

#include "sgtllc/types.h"

namespace sgtllc::io {

void appendCsvField(std::string& out, std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) {
    out.append(field);
    return;
  }
  out += '"';
  for (const char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

std::string csvField(std::string_view field) {
  std::string out;
  appendCsvField(out, field);
  return out;
}

CsvReader::CsvReader(std::string_view text, std::string source) : text_(text), source_(std::move(source)) {}

bool CsvReader::next(std::vector<std::string>& fields) {
  // Blank lines (LF or CRLF alone, or a last line of nothing but CR) are no records.
  while (pos_ < text_.size()) {
    if (text_[pos_] == '\n') {
      ++line_;
    } else if (text_[pos_] != '\r' || (pos_ + 1 < text_.size() && text_[pos_ + 1] != '\n')) {
      break;
    }
    ++pos_;
  }
  if (pos_ >= text_.size()) return false;
  record_line_ = line_;
  std::vector<std::string> out(1);
  const auto fail = [&](const std::string& what) {
    throw Error(source_ + ":" + std::to_string(line_) + ": " + what);
  };
  while (true) {
    std::string& field = out.back();
    if (pos_ < text_.size() && text_[pos_] == '"') {
      const size_t opened = line_;
      ++pos_;
      while (true) {
        if (pos_ >= text_.size()) {
          line_ = opened;
          fail("quoted field opened on this line is never closed (a '\"' inside a quoted field is written '\"\"')");
        }
        const char c = text_[pos_++];
        if (c == '"') {
          if (pos_ < text_.size() && text_[pos_] == '"') {
            field += '"';
            ++pos_;
            continue;
          }
          break;
        }
        if (c == '\n') ++line_;
        field += c;
      }
      const bool crlf = text_.compare(pos_, 2, "\r\n") == 0;
      if (pos_ < text_.size() && text_[pos_] != ',' && text_[pos_] != '\n' && !crlf) {
        fail("text after the closing quote of field " + std::to_string(out.size()) +
             " (a '\"' inside a quoted field is written '\"\"')");
      }
    } else {
      const size_t end = text_.find_first_of(",\n\"", pos_);
      const size_t stop = end == std::string_view::npos ? text_.size() : end;
      field.append(text_.substr(pos_, stop - pos_));
      pos_ = stop;
      if (pos_ < text_.size() && text_[pos_] == '"') {
        fail("a '\"' inside unquoted field " + std::to_string(out.size()) +
             " (a field with quotes is enclosed in quotes, its quotes doubled)");
      }
      // The CR of a CRLF ending belongs to no field.
      if ((pos_ >= text_.size() || text_[pos_] == '\n') && !field.empty() && field.back() == '\r') field.pop_back();
    }
    if (pos_ < text_.size() && text_[pos_] == '\r') ++pos_;  // after a quoted field: CRLF (checked above)
    if (pos_ >= text_.size()) break;
    if (text_[pos_] == '\n') {
      ++pos_;
      ++line_;
      break;
    }
    ++pos_;  // ','
    out.emplace_back();
  }
  fields = std::move(out);
  return true;
}

}  // namespace sgtllc::io
