#include "file_util.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>

namespace sgtllc::io {

FilePtr openForReading(const std::string& path) {
  // fopen succeeds on a directory under glibc and only the read fails, so catch that case with a clear message.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error("cannot open " + path + ": is a directory");
  FilePtr file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw Error("cannot open " + path + ": " + std::strerror(errno));
  return file;
}

std::string readWholeFile(const std::string& path) {
  FilePtr file = openForReading(path);
  std::string bytes;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);  // a hint: one allocation, and a size to refuse early
  if (!ec && size > loadableBytes()) {
    throw Error("cannot read " + path + ": " + std::to_string(size) + " bytes, more than this machine can load (" +
                gibText(loadableBytes()) + " of memory)");
  }
  try {
    if (!ec) bytes.reserve(static_cast<size_t>(size));
    char chunk[1 << 16];
    size_t n = 0;
    while ((n = std::fread(chunk, 1, sizeof(chunk), file.get())) > 0) bytes.append(chunk, n);
  } catch (const std::bad_alloc&) {
    throw Error("cannot read " + path + ": out of memory for " + std::to_string(ec ? bytes.size() : size) + " bytes");
  }
  if (std::ferror(file.get())) throw Error("cannot read " + path + ": " + std::strerror(errno));
  return bytes;
}

uint64_t loadableBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  uint64_t limit = pages > 0 && page > 0 ? static_cast<uint64_t>(pages) * static_cast<uint64_t>(page) : UINT64_MAX;
  struct rlimit as {};
  if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) limit = std::min<uint64_t>(limit, as.rlim_cur);
  return limit;
}

std::string gibText(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / (1024.0 * 1024.0 * 1024.0));
  return text;
}

}  // namespace sgtllc::io

namespace sgtllc::io::detail {

void checkNodeLabels(const std::string& path, const std::vector<Node>& nodes, int num_classes) {
  for (size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].label < 0 || nodes[i].label >= num_classes) {
      throw Error("cannot write " + path + ": node " + std::to_string(i) + " has label " +
                  std::to_string(nodes[i].label) + ", not a stable class index 0.." + std::to_string(num_classes - 1));
    }
  }
}

std::string_view nextLine(std::string_view text, size_t& pos) {
  const size_t end = std::min(text.find('\n', pos), text.size());
  const std::string_view line = text.substr(pos, end - pos);
  pos = std::min(end + 1, text.size());
  return line;
}

std::vector<std::string_view> splitBlanks(std::string_view line) {
  std::vector<std::string_view> tokens;
  size_t i = 0;
  while (i < line.size()) {
    const size_t start = line.find_first_not_of(" \t\r", i);
    if (start == std::string_view::npos) break;
    const size_t end = std::min(line.find_first_of(" \t\r", start), line.size());
    tokens.push_back(line.substr(start, end - start));
    i = end;
  }
  return tokens;
}

bool parseReal(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

namespace {

template <typename Real>
void appendReal(std::string& out, Real value) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof(buffer), value);  // shortest exact round trip
  out.append(buffer, ec == std::errc() ? end : buffer);
}

}  // namespace

void appendShortest(std::string& out, float value) { appendReal(out, value); }
void appendShortest(std::string& out, double value) { appendReal(out, value); }

std::optional<uint32_t> labelFromReal(double value) {
  if (!std::isfinite(value) || value < -2147483648.0 || value > 4294967295.0) return std::nullopt;
  return static_cast<uint32_t>(static_cast<int64_t>(std::llround(value)));
}

}  // namespace sgtllc::io::detail
