// Shared by the configuration suites (test_config_yaml.cpp, test_config_ranges.cpp).
#pragma once

#include <string>

#include "sgtllc/io/config_yaml.h"

namespace sgtllc::test {

/// The message parseConfig throws for @p yaml read as "my.yaml", or "(no error)".
inline std::string configErrorOf(const std::string& yaml) {
  try {
    io::parseConfig(yaml, "my.yaml");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace sgtllc::test
