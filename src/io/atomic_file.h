// Private to sgtllc_io: replacing a file in one step, for the writers of results a user keeps (trajectories, g2o
// graphs, loop lists). Whether an existing file may be replaced is the caller's decision (the CLI's --force).
#pragma once

#include <string>
#include <string_view>

namespace sgtllc::io::detail {

/// Writes @p content to `PATH.tmpPID` next to @p path, then renames it onto @p path, so readers never see half a
/// file and a failed write leaves any old file as it was. Throws sgtllc::Error `cannot write PATH: REASON`.
void writeFileAtomically(const std::string& path, std::string_view content);

}  // namespace sgtllc::io::detail
