#include "build_info.h"

#include <sys/utsname.h>

#include <ctime>
#include <fstream>
#include <thread>

#include "git_commit.h"  // generated at build time by cmake/SgtllcGitCommit.cmake

namespace sgtllc::cli {

std::string softwareText() { return "sgtllc " SGTLLC_VERSION ", commit " SGTLLC_GIT_COMMIT; }

std::string dateText() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  char buf[64];
  if (gmtime_r(&now, &utc) == nullptr || std::strftime(buf, sizeof(buf), "%Y-%m-%d %H:%M:%S UTC", &utc) == 0) {
    return "unknown";
  }
  return buf;
}

namespace {

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) break;
    const size_t start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? "unknown CPU" : line.substr(start);
  }
  return "unknown CPU";
}

}  // namespace

std::string machineText() {
  utsname u{};
  const std::string system =
      uname(&u) == 0 ? std::string(u.sysname) + " " + u.release + " " + u.machine : std::string("unknown system");
  const unsigned cores = std::thread::hardware_concurrency();
  return system + ", " + cpuModel() + ", " + (cores ? std::to_string(cores) : std::string("unknown")) + " cores";
}

eval::ReportInfo runInfo() {
  eval::ReportInfo info;
  info.software = softwareText();
  info.date = dateText();
  info.machine = machineText();
  return info;
}

}  // namespace sgtllc::cli
