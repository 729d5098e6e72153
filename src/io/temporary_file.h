// The temporary file behind every atomic write of output_file.h: created exclusively beside its destination,
// removed on every error path and on SIGINT/SIGTERM/SIGHUP, published by fsync + rename + folder fsync.
#pragma once

#include <string>
#include <string_view>

#include "sgtllc/io/output_file.h"

namespace sgtllc::io::detail {

/// A new empty file `FOLDER/.NAME.sgtllc-tmp-XXXXXXXXXXXX` (12 random letters and digits) for the destination
/// `FOLDER/NAME`, opened with O_CREAT|O_EXCL|O_NOFOLLOW|O_CLOEXEC and mode 0666 (less the umask, as any new file):
/// a name that exists — a file or a symlink someone placed there — is never opened, another is drawn. Until
/// publish() it is listed for the signal handler (removeOnSignal), and the destructor removes it. It holds an
/// exclusive flock(2) until it is renamed; the first temporary file a process makes in a folder removes the
/// unlocked ones there: leftovers of saves killed by SIGKILL, whose lock died with them.
class TemporaryFile {
 public:
  /// Throws sgtllc::Error `cannot write DESTINATION: REASON` if no temporary file can be created.
  explicit TemporaryFile(const std::string& destination);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return path_; }
  /// Writes all of @p bytes (throws `cannot write DESTINATION: REASON`).
  void write(std::string_view bytes);
  /// Throws unless the file at path() is still the one created here (a regular file, same inode): a writer that
  /// opened it by name (writeThroughTemporary) may have found something else there.
  void checkUnchanged() const;
  /// fsync, rename to the destination as @p overwrite says (refusing an existing one for kRefuse), then
  /// close and fsync the folder so the rename itself survives a power cut. Throws naming the destination; the temporary
  /// file is removed if any step fails.
  void publish(Overwrite overwrite);

 private:
  [[noreturn]] void fail(int err) const;
  std::string destination_;
  std::string path_;
  int fd_ = -1;
  int slot_ = -1;  ///< its place in the signal handler's list, or -1 when the list is full
  bool published_ = false;
};

}  // namespace sgtllc::io::detail
