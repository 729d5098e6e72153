/// @file quote.h
/// @brief Safe echo of file content in messages: a crafted file (or a file name found in a folder) must not reach
///        the user's terminal as control sequences.
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

/// Room for a whole name (a frame name, a file name found in a folder) where it is printed as output: PATH_MAX.
inline constexpr size_t kNameBytes = 4096;

/// @p text with only what a terminal would act on escaped: bytes below 0x20 other than tab and newline, DEL, C1
/// controls and invalid UTF-8 become `\xHH`; everything else (backslashes and quotes included) is kept, so text
/// that escapeContent() or quoteContent() already made safe comes back unchanged. The last guard of a whole
/// message (the CLI's error line) that may hold a path built from a folder's file names.
std::string escapeControls(std::string_view text);

}  // namespace sgtllc::io
