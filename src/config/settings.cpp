// The settings table's machinery (sgtllc/config/settings.h): ranges, access through a Config, the assembled table
// and its range checks. The tables themselves are settings_*.cpp.
#include "sgtllc/config/settings.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "config_ranges.h"
#include "setting_table.h"

namespace sgtllc {
namespace detail {
namespace {

double parseBound(const std::string& text, const std::string& whole) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') throw std::logic_error("settings table: bad range '" + whole + "'");
  return v;
}

}  // namespace

SettingRange parseRange(const std::string& text) {
  SettingRange r;
  std::string interval = text;
  if (text.rfind("0 (", 0) == 0) {  // "0 (MEANING) or [LO, HI]"
    const size_t close = text.find(") or ");
    if (close == std::string::npos) throw std::logic_error("settings table: bad range '" + text + "'");
    r.zero_means = text.substr(3, close - 3);
    interval = text.substr(close + 5);
  }
  const size_t comma = interval.find(", ");
  if (interval.size() < 5 || comma == std::string::npos || (interval.front() != '[' && interval.front() != '(') ||
      (interval.back() != ']' && interval.back() != ')')) {
    throw std::logic_error("settings table: bad range '" + text + "'");
  }
  r.lo_open = interval.front() == '(';
  r.hi_open = interval.back() == ')';
  r.lo = parseBound(interval.substr(1, comma - 1), text);
  r.hi = parseBound(interval.substr(comma + 2, interval.size() - comma - 3), text);
  return r;
}

}  // namespace detail

using namespace detail;

bool SettingRange::accepts(double v) const {
  if (!checked) return true;
  if (!zero_means.empty() && v == 0.0) return true;
  return inside(v, {lo, !lo_open}, {hi, !hi_open});
}

std::string SettingRange::text() const {
  if (!checked) return note;
  const std::string interval = detail::interval({lo, !lo_open}, {hi, !hi_open});
  return zero_means.empty() ? interval : "0 (" + zero_means + ") or " + interval;
}

double Setting::value(const Config& config) const { return get(section_of(const_cast<Config&>(config))); }

void Setting::assign(Config& config, double v) const { set(section_of(config), v); }

std::vector<uint32_t>& Setting::idList(Config& config) const { return *ids(section_of(config)); }

std::string Setting::choiceName(int v) const {
  for (const auto& choice : choices) {
    if (choice.second == v) return choice.first;
  }
  return "?";
}

std::string Setting::comment() const {
  // The unit goes after the meaning's first clause: "pairing distance (m); 0 = none", "… beyond this (m) ...".
  std::string c = meaning;
  if (!unit.empty()) {
    size_t at = c.find("; ");
    if (at == std::string::npos && c.size() > 4 && c.compare(c.size() - 4, 4, " ...") == 0) at = c.size() - 4;
    c.insert(at == std::string::npos ? c.size() : at, " (" + unit + ")");
  }
  if (!range.zero_means.empty()) c += "; 0 = " + range.zero_means;
  if (type == SettingType::kChoice) {
    std::string names;
    for (const auto& choice : choices) names += (names.empty() ? "" : " | ") + choice.first;
    c += " (" + names + ")";
  }
  return c;
}

namespace {

/// The settings before and after the cluster.NAME sections, which follow the class set; built once, as
/// Config::validate() runs on every comparePair call.
struct FixedSettings {
  std::vector<Setting> head, tail;
};

const FixedSettings& fixedSettings() {
  static const FixedSettings fixed = [] {
    FixedSettings f;
    addLabelSettings(&f.head);
    addLabellerSettings(&f.head);
    addStageSettings(&f.tail);
    addVerificationSettings(&f.tail);
    addRegistrationSettings(&f.tail);
    SectionTable<Config>("", [](Config& c) -> Config& { return c; }, &f.tail)
        .number("threads", &Config::threads, "[1, " + std::to_string(kMaxThreads) + "]", "",
                "worker threads for candidate verification; results do not depend on it");
    addBackendSettings(&f.tail);
    return f;
  }();
  return fixed;
}

}  // namespace

std::vector<Setting> settingsFor(const LabelConfig& labels) {
  const FixedSettings& fixed = fixedSettings();
  std::vector<Setting> s = fixed.head;
  addClusterSettings(labels, &s);
  s.insert(s.end(), fixed.tail.begin(), fixed.tail.end());
  return s;
}

std::vector<Setting> settingsOfSection(std::type_index section) {
  std::vector<Setting> of;
  for (Setting& s : settingsFor(LabelConfig{})) {
    if (s.section != section) continue;
    bool seen = false;
    for (const Setting& o : of) seen = seen || o.name == s.name;
    if (seen) continue;
    if (section == typeid(ClassClusterConfig)) s.key = "cluster.NAME." + s.name;  // one per class
    of.push_back(std::move(s));
  }
  return of;
}

void checkSettingRanges(const Config& config, const std::string& prefix) {
  const auto check = [&](const std::vector<Setting>& settings) {
    for (const Setting& s : settings) {
      if (s.type != SettingType::kReal && s.type != SettingType::kInteger) continue;
      if (s.key.compare(0, prefix.size(), prefix) != 0) continue;
      const double v = s.value(config);
      if (!s.range.accepts(v)) {
        outOfRange(s.key, s.type == SettingType::kInteger ? text(static_cast<long long>(v)) : text(v), s.range.text());
      }
    }
  };
  std::vector<Setting> cluster;
  addClusterSettings(config.labels, &cluster);
  check(fixedSettings().head);
  check(cluster);
  check(fixedSettings().tail);
}

}  // namespace sgtllc
