// Private to sgtllc_io: the kinds of value a configuration Field holds (config_fields.h) - numbers, integers,
// flags, named choices and lists of raw label ids - each with its printer and its parser, for the key table
// (config_fields.cpp) and the back end's keys (config_yaml_backend.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "config_fields.h"

namespace sgtllc::io::detail {

/// @p s as an integer in [@p lo, @p hi], all of it digits (and a sign).
bool parseInt(const std::string& s, long long lo, long long hi, long long* out);
/// The text of a scalar node; empty for a map, a list or null.
std::string scalarText(const YAML::Node& node);

/// A finite floating-point value, printed so that it reads back as a float.
Field number(std::string key, std::string comment, std::function<double&(Config&)> ref);
/// true or false.
Field boolean(std::string key, std::string comment, std::function<bool&(Config&)> ref);
/// A list of raw label ids, e.g. [10, 252] (registration.ground_ids).
Field idList(std::string key, std::string comment, std::function<std::vector<uint32_t>&(Config&)> ref);

/// A list of raw label ids, e.g. [10, 252]; returns an error text ("" on success).
std::string readIds(const YAML::Node& n, std::vector<uint32_t>* out);
/// @p ids as the YAML list readIds reads.
std::string idsText(const std::vector<uint32_t>& ids);

/// An integer within the range of @p T.
template <typename T>
Field integer(std::string key, std::string comment, std::function<T&(Config&)> ref) {
  return Field{std::move(key), std::move(comment),
               [ref](const Config& c) { return std::to_string(ref(const_cast<Config&>(c))); },
               [ref](Config& c, const YAML::Node& n) -> std::string {
                 long long v = 0;
                 const long long lo = std::numeric_limits<T>::min(), hi = std::numeric_limits<T>::max();
                 if (!parseInt(scalarText(n), lo, hi, &v)) {
                   return "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
                 }
                 ref(c) = static_cast<T>(v);
                 return "";
               }};
}

/// One of @p names; the comment lists them.
template <typename E>
Field choice(std::string key, std::string comment, std::function<E&(Config&)> ref,
             std::vector<std::pair<std::string, E>> names) {
  std::string options;
  for (const auto& [name, value] : names) options += (options.empty() ? "" : " | ") + name;
  comment += " (" + options + ")";
  return Field{std::move(key), std::move(comment),
               [ref, names](const Config& c) {
                 const E v = ref(const_cast<Config&>(c));
                 for (const auto& [name, value] : names) {
                   if (value == v) return name;
                 }
                 return std::string("?");
               },
               [ref, names, options](Config& c, const YAML::Node& n) -> std::string {
                 const std::string s = scalarText(n);
                 for (const auto& [name, value] : names) {
                   if (name == s) {
                     ref(c) = value;
                     return "";
                   }
                 }
                 return "expected one of " + options;
               }};
}

}  // namespace sgtllc::io::detail
