// Private to sgtllc_io: checks on a configuration's YAML text and keys that config_yaml.cpp runs around yaml-cpp.
#pragma once

#include <string>
#include <vector>

#include "config_fields.h"

namespace sgtllc::io::detail {

/// Throws `SOURCE:LINE: YAML aliases and anchors are not supported in sgtllc configs` at the first anchor (`&a`) or
/// alias (`*a`) of @p yaml. yaml-cpp's event parser reports them without expanding anything, so this costs one
/// linear pass even for a document whose aliases would expand to gigabytes (a "billion laughs" file), which
/// building the node tree and walking it would not. Malformed YAML throws YAML::Exception, as YAML::Load does.
void rejectAliases(const std::string& yaml, const std::string& source);

/// The known key closest to the unknown key @p name under section @p prefix ("" at the top level; a name is one
/// dotted part, a section name or a leaf), by edit distance with transpositions: "" unless it is close (at most
/// 2 edits, or a third of the name's length, and fewer edits than the name has characters).
std::string closestKey(const std::vector<Field>& fields, const std::string& prefix, const std::string& name);

}  // namespace sgtllc::io::detail
