// The settings table as Markdown (config_reference.h): what docs/configuration.md holds.
#include "sgtllc/io/config_reference.h"

#include <sstream>

#include "sgtllc/config/settings.h"
#include "sgtllc/io/config_yaml.h"

namespace sgtllc::io {
namespace {

/// A table cell: a '|' would end it.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string accepted(const Setting& s) {
  switch (s.type) {
    case SettingType::kReal:
    case SettingType::kInteger:
      return s.range.text();
    case SettingType::kFlag:
      return "true, false";
    case SettingType::kChoice: {
      std::string names;
      for (const auto& choice : s.choices) names += (names.empty() ? "`" : ", `") + choice.first + "`";
      return names;
    }
    case SettingType::kIdList:
      return "list of raw ids 0..65535";
    case SettingType::kCustom:
      break;
  }
  if (s.key == "labels.custom_map") return "map of raw id: class index or -1";
  if (s.key == "labels.extra_classes") return "list of {name, ids} (README \"Extra classes\")";
  return "distinct letters from i, j, k";
}

}  // namespace

std::string configReference(const Config& config) {
  std::ostringstream out;
  out << "# Configuration reference\n\n"
         "Every key of `sgtllc::Config`, its default, the values it accepts and what it means. Generated from the\n"
         "settings table (`include/sgtllc/config/settings.h`, `src/config/settings_*.cpp`) by\n"
         "`sgtllc config --markdown > docs/configuration.md`; a test checks that this file is current. Each class has\n"
         "a `cluster.NAME` section (the seven below, then any `labels.extra_classes`). Why each default was chosen:\n"
         "the comments of `include/sgtllc/config.h` and `include/sgtllc/config/`, and BENCHMARKS.md.\n";
  const std::vector<std::pair<std::string, std::string>> values = configValues(config);
  std::string section;
  size_t k = 0;
  for (const Setting& s : settingsFor(config.labels)) {
    const size_t dot = s.key.find('.');
    const std::string top = dot == std::string::npos ? "(top level)" : s.key.substr(0, dot);
    if (top != section) {
      section = top;
      out << "\n## " << section << "\n\n| key | default | accepts | meaning |\n|---|---|---|---|\n";
    }
    std::string meaning = s.meaning;
    if (!s.unit.empty()) meaning += " (" + s.unit + ")";
    out << "| `" << s.key << "` | `" << cell(values.at(k++).second) << "` | " << cell(accepted(s)) << " | "
        << cell(meaning) << " |\n";
  }
  return out.str();
}

}  // namespace sgtllc::io
