#include "atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "file_util.h"
#include "sgtllc/types.h"

namespace sgtllc::io::detail {

void writeFileAtomically(const std::string& path, std::string_view content) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error("cannot write " + path + ": is a directory");
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  try {
    writeFile(tmp, content);
  } catch (const Error& e) {
    fs::remove(tmp, ec);
    throw Error("cannot write " + path + " (" + e.what() + ")");
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw Error("cannot write " + path + ": " + ec.message());
  }
}

}  // namespace sgtllc::io::detail
