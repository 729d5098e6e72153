/// @file config_reference.h
/// @brief The settings table as a Markdown reference (`sgtllc config --markdown`, docs/configuration.md).
#pragma once

#include <string>

#include "sgtllc/config.h"

namespace sgtllc::io {

/// One table per section: every key of @p config's class set with its value in @p config, the values it accepts
/// (range, choices), its unit and meaning, from the settings table (sgtllc/config/settings.h).
std::string configReference(const Config& config);

}  // namespace sgtllc::io
