// Shared by the command-line suites (test_cli*.cpp): runs the built `sgtllc` and captures its output.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace sgtllc::test {

struct CliRun {
  int status = -1;
  std::string out;  // stdout, and stderr unless left out
};

/// Runs `sgtllc ARGS` through the shell; @p with_stderr = false drops stderr.
inline CliRun run(const std::string& args, bool with_stderr = true) {
  const std::string cmd = std::string(SGTLLC_CLI) + " " + args + (with_stderr ? " 2>&1" : " 2>/dev/null");
  CliRun r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int st = pclose(pipe);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

}  // namespace sgtllc::test
