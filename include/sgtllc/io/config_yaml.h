/// @file config_yaml.h
/// @brief sgtllc::Config as YAML: keys mirror the struct one to one (`graph.sigma_d`, `cluster.pole.min_size`, …).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sgtllc/config.h"

namespace sgtllc::io {

/// The whole configuration as commented YAML, in the format loadConfig reads (what `sgtllc config` prints).
std::string configToYaml(const Config& config);

/// Every configuration key with its value as configToYaml prints it (`{"graph.sigma_d", "30"}`, …), in print
/// order: the canonical text form a map file's configuration section stores (docs/map-format.md).
std::vector<std::pair<std::string, std::string>> configValues(const Config& config);

/// Applies the keys of a YAML document to the defaults; omitted keys keep their default values. Throws
/// sgtllc::Error naming @p source, the line and the key for malformed YAML, an unknown key, a value of the wrong
/// type, or a value out of range (Config::validate).
Config parseConfig(const std::string& yaml, const std::string& source = "<config>");

/// parseConfig on the contents of a file; the error names the file if it cannot be read.
Config loadConfig(const std::string& path);

}  // namespace sgtllc::io
