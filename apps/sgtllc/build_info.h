// The software, date and machine a report records (report.md's "Software", "Date" and "Machine" lines).
#pragma once

#include <string>

#include "sgtllc/eval/report.h"

namespace sgtllc::cli {

/// "sgtllc 0.1.0, commit 0158456abcde": the project version from CMake and (git describe at build time; "commit unknown" without .git, e.g. a tarball).
std::string softwareText();
/// The current time in UTC, ISO 8601 ("2026-12-02 02:40:11 UTC").
std::string dateText();
/// "Linux 6.1.0-13-amd64 x86_64, Intel(R) Xeon(R) ... CPU, 2 cores": uname, /proc/cpuinfo's model name and the
/// hardware threads; parts that cannot be read say "unknown".
std::string machineText();

/// A report's software, date and machine.
eval::ReportInfo runInfo();

}  // namespace sgtllc::cli
