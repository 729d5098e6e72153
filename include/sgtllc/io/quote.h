/// @file quote.h
/// @brief Safe echo of file content in messages: a crafted file must not reach the user's terminal as control
///        sequences (issue 15, defect 6).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace sgtllc::io {

/// @p content between single quotes, printable: bytes below 0x20, DEL, C1 controls (U+0080–U+009F) and invalid
/// UTF-8 become `\xHH`; tab, newline and carriage return become `\t`, `\n`, `\r`; a backslash or quote is
/// escaped with a backslash. Valid UTF-8 text is kept as it is. Content longer than @p max_bytes is cut at a
/// character boundary and followed by `... (N bytes)`. Every message that repeats bytes read from a file (header
/// values, tokens, field names, pair-list lines, file names found in a folder) passes them through here.
/// quoteContent() without the quotes, for content already set apart in its message (e.g. a list of names).
std::string escapeContent(std::string_view content, size_t max_bytes = 64);
/// (Not named `quoted`: argument-dependent lookup would pick std::quoted for a std::string.)
std::string quoteContent(std::string_view content, size_t max_bytes = 64);

}  // namespace sgtllc::io
