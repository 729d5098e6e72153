#include "sgtllc/io/output_file.h"

#include <unistd.h>

#include <filesystem>

#include "sgtllc/types.h"
#include "temporary_file.h"

namespace fs = std::filesystem;

namespace sgtllc::io {

void checkOutputFile(const std::string& path, Overwrite overwrite, bool folder_may_be_created) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw Error("cannot write " + path + ": is a directory");
  if (fs::exists(fs::symlink_status(path, ec)) && overwrite == Overwrite::kRefuse) {
    throw Error(path + ": file exists; choose another name or pass --force to overwrite it");
  }
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
  detail::TemporaryFile tmp(path);
  tmp.write(content);
  tmp.publish(overwrite);
}

void writeFileAtomically(const std::string& path, const std::vector<std::string_view>& pieces, Overwrite overwrite) {
  constexpr size_t kGather = size_t{1} << 20;
  detail::TemporaryFile tmp(path);
  std::string gathered;
  for (std::string_view piece : pieces) {
    if (gathered.size() + piece.size() > kGather && !gathered.empty()) {
      tmp.write(gathered);
      gathered.clear();
    }
    if (piece.size() >= kGather) {
      tmp.write(piece);
    } else {
      gathered += piece;
    }
  }
  tmp.write(gathered);
  tmp.publish(overwrite);
}

void writeThroughTemporary(const std::string& path, Overwrite overwrite,
                           const std::function<void(const std::string& tmp)>& write) {
  detail::TemporaryFile tmp(path);
  write(tmp.path());
  tmp.checkUnchanged();
  tmp.publish(overwrite);
}

}  // namespace sgtllc::io
