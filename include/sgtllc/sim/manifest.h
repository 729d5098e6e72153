/// @file manifest.h
/// @brief simulation.txt: the settings a simulated sequence was written with, so that a second session can
///        rebuild its world (`sgtllc simulate --world-of`, docs/relocalization.md).
///
/// One `key value` pair a line after a comment line; a second session adds its first session's settings under
/// keys prefixed `first.`. Numbers are written in their shortest exact form, so a config reads back bit for bit.
/// The sensor is recorded by its preset name only (the CLI offers nothing else).
#pragma once

#include <string>

#include "sgtllc/io/output_file.h"
#include "sgtllc/sim/simulator.h"

namespace sgtllc::sim {

/// File name of the manifest inside a sequence folder.
inline constexpr const char* kManifestName = "simulation.txt";
/// Format version this build writes and the newest it reads.
inline constexpr int kManifestFormat = 1;

/// The manifest of a sequence simulated with @p config.
std::string manifestText(const SimConfig& config);

/// Parses manifestText()'s format; throws sgtllc::Error `PATH: line N: PROBLEM` (unknown or repeated key, bad
/// value, missing key, newer format). @p path only names the file in messages.
SimConfig parseManifest(const std::string& text, const std::string& path);

/// Writes DIR/simulation.txt (io::writeFileAtomically).
void writeManifest(const std::string& dir, const SimConfig& config, io::Overwrite overwrite);

/// Reads DIR/simulation.txt. A folder without one gets a message that says why (not a simulated sequence, or one
/// written before sgtllc wrote manifests) and how to get one.
SimConfig readManifest(const std::string& dir);

}  // namespace sgtllc::sim
