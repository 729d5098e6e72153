/// @file output_file.h
/// @brief How every sgtllc writer creates a file: never half a file, and never over a file the user did not
///        agree to lose (issue 15, defect 3).
///
/// A file is written to a temporary name beside its destination and renamed into place. With
/// Overwrite::kRefuse the rename itself refuses an existing destination (Linux renameat2 RENAME_NOREPLACE, or a
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

/// For files another library writes (PNG plots): calls @p write with a temporary name beside @p path, then renames
/// that file to @p path as writeFileAtomically() does. The temporary file is removed if either step fails.
void writeThroughTemporary(const std::string& path, Overwrite overwrite,
                           const std::function<void(const std::string& tmp)>& write);

}  // namespace sgtllc::io
