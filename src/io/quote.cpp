#include "sgtllc/io/quote.h"

#include <cstdint>

namespace sgtllc::io {
namespace {

/// Length of the valid UTF-8 sequence starting at @p i (2–4 bytes, shortest form, no surrogates, at most
/// U+10FFFF) whose code point is printable (not a C1 control); 0 if there is none.
size_t printableUtf8(std::string_view s, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = byte(i);
  size_t n = 0;
  uint32_t cp = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    n = 2;
    cp = lead & 0x1Fu;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    n = 3;
    cp = lead & 0x0Fu;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    n = 4;
    cp = lead & 0x07u;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  }
  const uint32_t smallest[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < smallest[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return cp < 0xA0 ? 0 : n;
}

/// Appends `\xHH` of @p c.
void appendHex(std::string& out, unsigned char c) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += "\\x";
  out += kHex[c >> 4];
  out += kHex[c & 0xF];
}

/// Appends the escaped text of @p content (up to @p max_bytes of it) to @p out; returns the bytes consumed.
size_t appendEscaped(std::string& out, std::string_view content, size_t max_bytes) {
  size_t i = 0;
  while (i < content.size() && i < max_bytes) {
    const unsigned char c = static_cast<unsigned char>(content[i]);
    if (c >= 0x80) {
      const size_t n = printableUtf8(content, i);
      if (n > 0 && i + n <= max_bytes) {
        out.append(content.substr(i, n));
        i += n;
        continue;
      }
      if (n > 0) break;  // a character that does not fit whole is left out with the rest
    }
    switch (c) {
      case '\\': out += "\\\\"; break;
      case '\'': out += "\\'"; break;
      case '\t': out += "\\t"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20 || c >= 0x7F) {
          appendHex(out, c);
        } else {
          out += static_cast<char>(c);
        }
    }
    ++i;
  }
  return i;
}

std::string truncation(std::string_view content, size_t consumed) {
  return consumed < content.size() ? "... (" + std::to_string(content.size()) + " bytes)" : "";
}

}  // namespace

std::string escapeContent(std::string_view content, size_t max_bytes) {
  std::string out;
  const size_t consumed = appendEscaped(out, content, max_bytes);
  return out + truncation(content, consumed);
}

std::string quoteContent(std::string_view content, size_t max_bytes) {
  std::string out = "'";
  const size_t consumed = appendEscaped(out, content, max_bytes);
  return out + "'" + truncation(content, consumed);
}

std::string escapeControls(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  size_t i = 0;
  while (i < text.size()) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      if (const size_t n = printableUtf8(text, i)) {
        out.append(text.substr(i, n));
        i += n;
        continue;
      }
    }
    if ((c < 0x20 && c != '\t' && c != '\n') || c >= 0x7F) {
      appendHex(out, c);
    } else {
      out += static_cast<char>(c);
    }
    ++i;
  }
  return out;
}

}  // namespace sgtllc::io
