#include "sgtllc/io/output_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "sgtllc/types.h"

namespace fs = std::filesystem;

namespace sgtllc::io {
namespace {

[[noreturn]] void exists(const std::string& path) {
  throw Error(path + ": file exists; choose another name or pass --force to overwrite it");
}

/// rename(2) that fails with EEXIST instead of replacing @p to.
int renameNoReplace(const char* from, const char* to) {
#ifdef RENAME_NOREPLACE
  if (::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_NOREPLACE) == 0) return 0;
  if (errno != EINVAL && errno != ENOSYS) return -1;
#endif
  // No RENAME_NOREPLACE on this file system: link(2) never replaces either.
  if (::link(from, to) != 0) return -1;
  ::unlink(from);
  return 0;
}

/// A temporary name beside @p path, unique per process and call (parallel writers use distinct paths anyway).
std::string temporaryPathFor(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  return path + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

/// Renames @p tmp to @p path as @p overwrite says; removes @p tmp if that fails.
void publishFile(const std::string& tmp, const std::string& path, Overwrite overwrite) {
  const int rc = overwrite == Overwrite::kReplace ? std::rename(tmp.c_str(), path.c_str())
                                                   : renameNoReplace(tmp.c_str(), path.c_str());
  if (rc == 0) return;
  const int err = errno;
  ::unlink(tmp.c_str());
  if (err == EEXIST) exists(path);
  throw Error("cannot write " + path + ": " + std::strerror(err));
}

}  // namespace

void checkOutputFile(const std::string& path, Overwrite overwrite, bool folder_may_be_created) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error("cannot write " + path + ": is a directory");
  if (fs::exists(fs::symlink_status(path, ec)) && overwrite == Overwrite::kRefuse) exists(path);
  // Probe the folder now, so a bad path fails before minutes of work rather than after.
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  while (folder_may_be_created && !fs::exists(folder, ec)) {  // ends at "." or "/", which exist
    const fs::path up = folder.parent_path();
    folder = up.empty() ? fs::path(".") : up;
  }
  if (!fs::is_directory(folder, ec)) {
    throw Error("cannot write " + path + ": folder " + folder.string() +
                (fs::exists(folder, ec) ? " is not a folder" : " does not exist"));
  }
  if (::access(folder.c_str(), W_OK) != 0) {
    throw Error("cannot write " + path + ": folder " + folder.string() + " is not writable");
  }
}

void checkOutputFiles(const std::vector<std::string>& paths, Overwrite overwrite, bool folders_may_be_created) {
  for (const std::string& p : paths) checkOutputFile(p, overwrite, folders_may_be_created);
}

void writeFileAtomically(const std::string& path, std::string_view content, Overwrite overwrite) {
  const std::string tmp = temporaryPathFor(path);
  std::FILE* file = std::fopen(tmp.c_str(), "wb");
  if (!file) throw Error("cannot write " + path + ": " + std::strerror(errno));
  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  const int write_errno = errno;
  if (std::fclose(file) != 0 || !written) {
    const int err = written ? errno : write_errno;
    ::unlink(tmp.c_str());
    throw Error("cannot write " + path + ": " + std::strerror(err));
  }
  publishFile(tmp, path, overwrite);
}

void writeThroughTemporary(const std::string& path, Overwrite overwrite,
                           const std::function<void(const std::string& tmp)>& write) {
  const std::string tmp = temporaryPathFor(path);
  try {
    write(tmp);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
  publishFile(tmp, path, overwrite);
}

}  // namespace sgtllc::io
