/// @file output_file.h
/// @brief How every sgtllc writer creates a file: never half a file, never through a link someone placed, and
///        never over a file the user did not agree to lose.
///
/// A file is written to a temporary file beside its destination and renamed into place:
/// - The temporary file is `FOLDER/.NAME.sgtllc-tmp-XXXXXXXXXXXX` for `FOLDER/NAME` (12 random letters and
///   digits; isTemporaryFileName()), created with O_CREAT|O_EXCL|O_NOFOLLOW and mode 0666 less the umask, as any
///   new file: a file or symlink already at that name is never opened or followed, so a link planted in the folder
///   cannot redirect a save, and the name cannot be guessed in advance.
/// - Its data are fsynced before the rename and the folder after it: after a power cut the destination holds the
///   old file or the whole new one.
/// - It is removed on every error path, and on SIGINT, SIGTERM and SIGHUP when their action was the default one (a
///   handler is installed once, at the first save, unlinks the live temporary files with async-signal-safe calls
///   and re-raises the signal; an application's own handlers are left alone, the library prints nothing).
/// - A process killed by SIGKILL (or a power cut) cannot remove it: such a leftover keeps the hidden, recognisable
///   name, never the destination's, so no reader takes it for output (the sequence and node-folder readers list
///   `*.bin` / `*.txt` only, and the name ends in the random letters), and the next save into that folder removes
///   it: a live temporary file holds a flock(2) until its rename, which dies with its process, so an unlocked one is
///   a leftover (temporary_file.h).
///
/// With Overwrite::kRefuse the rename itself refuses an existing destination (Linux renameat2 RENAME_NOREPLACE, or a
/// hard link where the file system lacks it), so a file that appeared after the up-front check is still kept.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace sgtllc::io {

/// What a writer does when its destination already exists.
enum class Overwrite {
  kRefuse,   ///< throw `PATH: file exists; ...` and leave the file as it was (the CLI without --force)
  kReplace,  ///< replace it (atomically: readers see the old or the new file, never a mix)
};

/// `kReplace` if @p force, else `kRefuse`: the CLI's --force flag.
inline Overwrite overwriteIf(bool force) { return force ? Overwrite::kReplace : Overwrite::kRefuse; }

/// Throws sgtllc::Error unless @p path can be created: it is a directory; it exists and @p overwrite is kRefuse
/// (`PATH: file exists; choose another name or pass --force to overwrite it`); or its folder does not exist or is
/// not writable. With @p folder_may_be_created, a missing folder is fine if its nearest existing ancestor is a
/// writable folder. Writers call it for every file before any work, and again (implicitly) at the final rename.
void checkOutputFile(const std::string& path, Overwrite overwrite, bool folder_may_be_created = false);
/// checkOutputFile() on each of @p paths.
void checkOutputFiles(const std::vector<std::string>& paths, Overwrite overwrite, bool folders_may_be_created = false);

/// Writes @p content to a temporary file beside @p path and renames it to @p path as @p overwrite says. Throws
/// sgtllc::Error naming @p path; the temporary file never stays behind.
void writeFileAtomically(const std::string& path, std::string_view content, Overwrite overwrite);
/// The same for content given as @p pieces in order (a big file written from where its parts lie, not joined in
/// memory first); small pieces are gathered into writes of about a megabyte.
void writeFileAtomically(const std::string& path, const std::vector<std::string_view>& pieces, Overwrite overwrite);

/// For files another library writes by name (PNG plots): creates the temporary file exclusively as
/// writeFileAtomically() does, calls @p write with its name (the writer truncates and fills it), checks that the
/// name still holds that same regular file, then publishes it likewise. The temporary file is removed if any step
/// fails.
void writeThroughTemporary(const std::string& path, Overwrite overwrite,
                           const std::function<void(const std::string& tmp)>& write);

/// True for a name of the form `.NAME.sgtllc-tmp-XXXXXXXXXXXX` (12 letters or digits): a temporary file of a save,
/// or one left by a killed process. A file name, not a path.
bool isTemporaryFileName(std::string_view filename);

}  // namespace sgtllc::io
