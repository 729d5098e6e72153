// How a setting is printed and read in YAML, by its type (config_field_kinds.h).
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

Field fieldOf(const Setting& setting) {
  Field f{setting.key, setting.comment(), nullptr, nullptr};
  // Settings are copied into the closures: the table that made them is gone by the time they run.
  switch (setting.type) {
    case SettingType::kReal:
      f.print = [setting](const Config& c) { return formatDouble(setting.value(c)); };
      f.set = [setting](Config& c, const YAML::Node& n) -> std::string {
        double v = 0.0;
        if (!parseDouble(scalarText(n), &v)) return "expected a finite number";
        setting.assign(c, v);
        return "";
      };
      break;
    case SettingType::kInteger:
      f.print = [setting](const Config& c) { return std::to_string(static_cast<long long>(setting.value(c))); };
      f.set = [setting](Config& c, const YAML::Node& n) -> std::string {
        long long v = 0;
        const auto lo = static_cast<long long>(setting.storage_lo), hi = static_cast<long long>(setting.storage_hi);
        if (!parseInt(scalarText(n), lo, hi, &v)) {
          return "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
        }
        setting.assign(c, static_cast<double>(v));
        return "";
      };
      break;
    case SettingType::kFlag:
      f.print = [setting](const Config& c) { return std::string(setting.value(c) != 0.0 ? "true" : "false"); };
      f.set = [setting](Config& c, const YAML::Node& n) -> std::string {
        const std::string s = scalarText(n);
        if (s != "true" && s != "false") return "expected true or false";
        setting.assign(c, s == "true" ? 1.0 : 0.0);
        return "";
      };
      break;
    case SettingType::kChoice:
      f.print = [setting](const Config& c) { return setting.choiceName(static_cast<int>(setting.value(c))); };
      f.set = [setting](Config& c, const YAML::Node& n) -> std::string {
        const std::string s = scalarText(n);
        std::string options;
        for (const auto& [name, value] : setting.choices) {
          if (name == s) {
            setting.assign(c, value);
            return "";
          }
          options += (options.empty() ? "" : " | ") + name;
        }
        return "expected one of " + options;
      };
      break;
    case SettingType::kIdList:
      f.print = [setting](const Config& c) { return idsText(setting.idList(const_cast<Config&>(c))); };
      f.set = [setting](Config& c, const YAML::Node& n) -> std::string { return readIds(n, &setting.idList(c)); };
      break;
    case SettingType::kCustom:
      break;  // config_fields.cpp's own
  }
  return f;
}

}  // namespace sgtllc::io::detail
