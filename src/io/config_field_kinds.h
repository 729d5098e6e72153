// Private to sgtllc_io: how a setting of the table (sgtllc/config/settings.h) is printed and read in YAML - numbers,
// integers, flags, named choices and lists of raw label ids - for the key table (config_fields.cpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "config_fields.h"
#include "sgtllc/config/settings.h"

namespace sgtllc::io::detail {

/// @p s as an integer in [@p lo, @p hi], all of it digits (and a sign).
bool parseInt(const std::string& s, long long lo, long long hi, long long* out);
/// The text of a scalar node; empty for a map, a list or null.
std::string scalarText(const YAML::Node& node);

/// A list of raw label ids, e.g. [10, 252]; returns an error text ("" on success).
std::string readIds(const YAML::Node& n, std::vector<uint32_t>* out);
/// @p ids as the YAML list readIds reads.
std::string idsText(const std::vector<uint32_t>& ids);

/// The Field of a setting of every type but kCustom: its comment, printer and parser.
Field fieldOf(const Setting& setting);

}  // namespace sgtllc::io::detail
