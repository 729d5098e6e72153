/// @file csv.h
/// @brief CSV fields as RFC 4180 writes them: every CSV sgtllc writes or reads goes through here, so that a frame
///        name with a comma, a quote or a newline (a file name is any byte string) keeps its columns.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace sgtllc::io {

/// Appends @p field to @p out as one CSV field: enclosed in double quotes, with inner quotes doubled, if it holds a
/// comma, a double quote, CR or LF (RFC 4180 §2.6–2.7); unchanged otherwise, so ordinary names and numbers are
/// written as they always were.
void appendCsvField(std::string& out, std::string_view field);

/// appendCsvField into a new string.
std::string csvField(std::string_view field);

/// Reads the records of a CSV text one by one. Fields may be quoted as appendCsvField writes them (a quoted field
/// may hold commas, doubled quotes, CR and LF); a record ends at an LF outside quotes, and the CR of a CRLF ending
/// is dropped. Blank lines are skipped. Throws sgtllc::Error naming @p source and the line for an unterminated
/// quoted field, text after a field's closing quote, or a quote inside an unquoted field.
class CsvReader {
 public:
  /// @p text must outlive the reader; @p source names it in messages (a path).
  CsvReader(std::string_view text, std::string source);

  /// The next record's fields into @p fields; false (and @p fields untouched) at the end of the text.
  bool next(std::vector<std::string>& fields);

  /// 1-based line on which the record last returned by next() starts.
  size_t line() const { return record_line_; }

  /// "SOURCE:LINE" of that record, for messages.
  std::string at() const { return source_ + ":" + std::to_string(record_line_); }

 private:
  std::string_view text_;
  std::string source_;
  size_t pos_ = 0;
  size_t line_ = 1;  // line of text_[pos_]
  size_t record_line_ = 0;
};

}  // namespace sgtllc::io
