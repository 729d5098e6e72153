#include "temporary_file.h"

#include <fcntl.h>
#include <limits.h>
#include <dirent.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <mutex>
#include <random>
#include <set>

#include "sgtllc/types.h"

namespace fs = std::filesystem;

namespace sgtllc::io::detail {
namespace {

// --- the temporary files a signal must remove ---------------------------------------------------------------
// A fixed table, so the handler touches no allocator and no lock: only lock-free atomics and unlink(2), both
// async-signal-safe. A slot is free (0), being filled or emptied (1: the handler skips it) or live (2).
static_assert(std::atomic<int>::is_always_lock_free);
constexpr int kSlots = 64;
struct Slot {
  std::atomic<int> state{0};
  char path[PATH_MAX] = {};  // initialised, so the table is constant-initialised (zero pages) and costs no start-up
};
Slot g_slots[kSlots];

extern "C" void removeTemporariesAndReraise(int sig) {
  const int saved_errno = errno;
  for (Slot& slot : g_slots) {
    if (slot.state.load(std::memory_order_acquire) == 2) ::unlink(slot.path);
  }
  errno = saved_errno;
  // SA_RESETHAND restored the default action; the signal stays blocked until this handler returns, then ends the
  // process as it would have without us (exit status, core dump).
  ::raise(sig);
}

/// Installs the handler, once, for each of SIGINT, SIGTERM and SIGHUP whose action is still the default one (the
/// process would die leaving the file): a handler of the application's own (Python's KeyboardInterrupt) or an
/// ignored signal is left as it is, and the save then ends normally or through its error path.
void installSignalHandlerOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0) continue;
      if ((old.sa_flags & SA_SIGINFO) != 0 || old.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = removeTemporariesAndReraise;
      sigemptyset(&action.sa_mask);
      for (const int other : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, other);
      action.sa_flags = SA_RESETHAND;
      ::sigaction(sig, &action, nullptr);
    }
  });
}

/// Lists @p path for the handler; -1 if it does not fit (the file is then removed on errors only).
int listForSignals(const std::string& path) {
  installSignalHandlerOnce();
  std::error_code ec;
  const std::string absolute = fs::absolute(path, ec).string();  // a later chdir must not retarget the unlink
  if (ec || absolute.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!g_slots[i].state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) continue;
    std::memcpy(g_slots[i].path, absolute.c_str(), absolute.size() + 1);
    g_slots[i].state.store(2, std::memory_order_release);
    return i;
  }
  return -1;
}

void unlist(int slot) {
  if (slot >= 0) g_slots[slot].state.store(0, std::memory_order_release);
}

// --- names -----------------------------------------------------------------------------------------------------

constexpr std::string_view kMarker = ".sgtllc-tmp-";
constexpr size_t kRandomLetters = 12;
constexpr size_t kMaxKeptName = 200;  // NAME_MAX is 255: room for the dot, the marker and the letters

std::string randomLetters() {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char raw[kRandomLetters];
  if (::getrandom(raw, sizeof raw, 0) != static_cast<ssize_t>(sizeof raw)) {
    std::random_device device;  // getrandom(2) missing (old kernel): the C++ library's own source
    for (unsigned char& b : raw) b = static_cast<unsigned char>(device());
  }
  std::string letters;
  for (unsigned char b : raw) letters += kAlphabet[b % (sizeof kAlphabet - 1)];
  return letters;
}

std::string temporaryPathFor(const std::string& destination) {
  const fs::path dest(destination);
  const std::string name = dest.filename().string().substr(0, kMaxKeptName);
  return (dest.parent_path() / ("." + name + std::string(kMarker) + randomLetters())).string();
}

/// True for a file that another save may have just created and not yet locked: open(2) and flock(2) are two
/// calls, and between them the file is empty and new. Such a file is left for a later save to judge; a save
/// killed before its first byte leaves nothing worth hurrying for.
bool mayBeBeingCreated(const struct stat& st) {
  constexpr time_t kCreationWindowSeconds = 60;
  const time_t now = ::time(nullptr);
  return st.st_size == 0 && st.st_mtime > now - kCreationWindowSeconds;
}

/// Removes the temporary files in @p folder that a killed save left behind (kill -9 runs no handler), once per
/// folder and process. A live temporary file holds an exclusive flock(2) from its creation until its rename, and
/// the kernel drops the lock when its process dies, so a temporary file whose lock can be taken is a leftover;
/// one whose lock is held (another save, in this process or another) is left alone.
void removeLeftovers(const fs::path& folder) {
  static std::mutex mutex;
  static std::set<std::string> done;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (!done.insert(folder.string()).second) return;
  }
  const std::string dir = folder.empty() ? "." : folder.string();
  DIR* d = ::opendir(dir.c_str());
  if (!d) return;
  while (const dirent* e = ::readdir(d)) {
    if (!isTemporaryFileName(e->d_name)) continue;
    const int fd = ::openat(::dirfd(d), e->d_name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && !mayBeBeingCreated(st) && ::flock(fd, LOCK_EX | LOCK_NB) == 0) {
      ::unlinkat(::dirfd(d), e->d_name, 0);
    }
    ::close(fd);
  }
  ::closedir(d);
}

}  // namespace

TemporaryFile::TemporaryFile(const std::string& destination) : destination_(destination) {
  // A name that exists is drawn again: 62^12 names, so only someone creating names on purpose makes that happen.
  for (int attempt = 0; attempt < 100; ++attempt) {
    path_ = temporaryPathFor(destination);
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0) break;
    if (errno != EEXIST) fail(errno);
  }
  if (fd_ < 0) fail(EEXIST);
  // Before the first byte: removeLeftovers locks only files that are not empty or not new (mayBeBeingCreated).
  ::flock(fd_, LOCK_EX);
  slot_ = listForSignals(path_);
  removeLeftovers(fs::path(destination).parent_path());
}

TemporaryFile::~TemporaryFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!published_) ::unlink(path_.c_str());
  unlist(slot_);
}

void TemporaryFile::fail(int err) const { throw Error("cannot write " + destination_ + ": " + std::strerror(err)); }

void TemporaryFile::write(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : EIO);
    bytes.remove_prefix(static_cast<size_t>(n));
  }
}

void TemporaryFile::checkUnchanged() const {
  struct stat ours {}, there {};
  if (::fstat(fd_, &ours) != 0) fail(errno);
  if (::lstat(path_.c_str(), &there) != 0) fail(errno);
  if (!S_ISREG(there.st_mode) || there.st_ino != ours.st_ino || there.st_dev != ours.st_dev) {
    throw Error("cannot write " + destination_ + ": its temporary file " + path_ + " was replaced while it was written");
  }
}

namespace {

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

/// Makes a rename in @p folder durable. Best effort: some file systems refuse fsync on a folder (EINVAL), and the
/// file is in place already, so a failure here is not reported as a failed write.
void syncFolder(const fs::path& folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void TemporaryFile::publish(Overwrite overwrite) {
  // The data reach the disk before the name does: a power cut leaves the old file or the whole new one. The file
  // stays open, and so locked, until its temporary name is gone (removeLeftovers must not take it for a leftover).
  if (::fsync(fd_) != 0) fail(errno);
  const int rc = overwrite == Overwrite::kReplace ? std::rename(path_.c_str(), destination_.c_str())
                                                   : renameNoReplace(path_.c_str(), destination_.c_str());
  if (rc != 0) {
    if (errno == EEXIST) {
      throw Error(destination_ + ": file exists; choose another name or pass --force to overwrite it");
    }
    fail(errno);
  }
  published_ = true;
  unlist(slot_);
  slot_ = -1;
  ::close(fd_);  // fsynced already: nothing is left for close(2) to report
  fd_ = -1;
  syncFolder(fs::path(destination_).parent_path());
}

}  // namespace sgtllc::io::detail

namespace sgtllc::io {

bool isTemporaryFileName(std::string_view filename) {
  const size_t at = filename.rfind(detail::kMarker);
  if (filename.empty() || filename.front() != '.' || at == std::string_view::npos || at == 0) return false;
  const std::string_view letters = filename.substr(at + detail::kMarker.size());
  if (letters.size() != detail::kRandomLetters) return false;
  for (const char c : letters) {
    if (!std::isalnum(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

}  // namespace sgtllc::io
