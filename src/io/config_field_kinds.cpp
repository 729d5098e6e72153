// The kinds of value a configuration Field holds (config_field_kinds.h): their printers and parsers.
#include "config_field_kinds.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace sgtllc::io::detail {
namespace {

std::string formatDouble(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof(buf), v);
  std::string s(buf, res.ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep floats recognisable as floats
  return s;
}

bool parseDouble(const std::string& s, double* out) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *out = std::strtod(s.c_str(), &end);
  return errno == 0 && end == s.c_str() + s.size() && std::isfinite(*out);
}

}  // namespace

bool parseInt(const std::string& s, long long lo, long long hi, long long* out) {
  if (s.empty()) return false;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), *out);
  return res.ec == std::errc() && res.ptr == s.data() + s.size() && *out >= lo && *out <= hi;
}

std::string scalarText(const YAML::Node& node) { return node.IsScalar() ? node.Scalar() : std::string(); }

Field number(std::string key, std::string comment, std::function<double&(Config&)> ref) {
  return Field{std::move(key), std::move(comment),
               [ref](const Config& c) { return formatDouble(ref(const_cast<Config&>(c))); },
               [ref](Config& c, const YAML::Node& n) -> std::string {
                 double v = 0.0;
                 if (!parseDouble(scalarText(n), &v)) return "expected a finite number";
                 ref(c) = v;
                 return "";
               }};
}

Field boolean(std::string key, std::string comment, std::function<bool&(Config&)> ref) {
  return Field{std::move(key), std::move(comment),
               [ref](const Config& c) { return std::string(ref(const_cast<Config&>(c)) ? "true" : "false"); },
               [ref](Config& c, const YAML::Node& n) -> std::string {
                 const std::string s = scalarText(n);
                 if (s != "true" && s != "false") return "expected true or false";
                 ref(c) = (s == "true");
                 return "";
               }};
}

std::string readIds(const YAML::Node& n, std::vector<uint32_t>* out) {
  if (!n.IsSequence()) return "expected a list of raw ids, e.g. [10, 252]";
  out->clear();
  for (const auto& id : n) {
    long long v = 0;
    if (!parseInt(scalarText(id), 0, 0xFFFF, &v)) return "ids must be integers 0..65535";
    out->push_back(static_cast<uint32_t>(v));
  }
  return "";
}

std::string idsText(const std::vector<uint32_t>& ids) {
  std::string s = "[";
  for (size_t k = 0; k < ids.size(); ++k) s += (k ? ", " : "") + std::to_string(ids[k]);
  return s + "]";
}

Field idList(std::string key, std::string comment, std::function<std::vector<uint32_t>&(Config&)> ref) {
  return Field{std::move(key), std::move(comment),
               [ref](const Config& c) { return idsText(ref(const_cast<Config&>(c))); },
               [ref](Config& c, const YAML::Node& n) -> std::string { return readIds(n, &ref(c)); }};
}

}  // namespace sgtllc::io::detail
