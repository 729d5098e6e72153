// Private to sgtllc_io: the table of configuration keys that config_yaml.cpp prints and reads. Each key of
// sgtllc::Config (include/sgtllc/config.h) is one Field; the cluster.NAME keys follow the class set.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sgtllc/config.h"

namespace sgtllc::io::detail {

/// One configuration leaf: its dotted key, its comment, and how to print and set it.
struct Field {
  std::string key;
  std::string comment;
  std::function<std::string(const Config&)> print;
  /// Sets the value from a YAML node; returns an error text ("" on success).
  std::function<std::string(Config&, const YAML::Node&)> set;
};

/// Every key, in print order, for the class set of @p labels (one cluster.NAME section per class).
std::vector<Field> fieldsFor(const LabelConfig& labels);

}  // namespace sgtllc::io::detail
