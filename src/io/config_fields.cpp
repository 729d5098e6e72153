// The configuration key table: one Field per setting of the settings table (sgtllc/config/settings.h), printed and
// parsed by its type (config_field_kinds.cpp); here the three settings with a syntax of their own.
#include "config_fields.h"

#include <stdexcept>
#include <utility>

#include "config_field_kinds.h"
#include "sgtllc/io/quote.h"

namespace sgtllc::io::detail {
namespace {

Field customMap(const Setting& setting) {
  return Field{
      setting.key, setting.comment(),
      [](const Config& c) {
        std::string s = "{";
        for (const auto& [id, cls] : c.labels.custom_map) {
          s += (s.size() > 1 ? ", " : "") + std::to_string(id) + ": " + std::to_string(cls);
        }
        return s + "}";
      },
      [](Config& c, const YAML::Node& n) -> std::string {
        if (!n.IsMap() && !n.IsNull()) return "expected a map of id: class";
        c.labels.custom_map.clear();
        if (n.IsNull()) return "";
        const int last = c.labels.numClasses() - 1;  // labels.extra_classes is read first (parseConfig)
        for (const auto& kv : n) {
          long long id = 0, cls = 0;
          if (!parseInt(scalarText(kv.first), 0, 0xFFFF, &id)) return "ids must be integers 0..65535";
          if (!parseInt(scalarText(kv.second), -1, last, &cls)) {
            return "classes must be integers -1.." + std::to_string(last) + " (id " + std::to_string(id) + ")";
          }
          // Spellings such as 50 and 050 pass the duplicate-key scan but name the same id.
          if (c.labels.custom_map.count(static_cast<uint32_t>(id))) {
            return "id " + std::to_string(id) + " is listed twice";
          }
          c.labels.custom_map[static_cast<uint32_t>(id)] = static_cast<int>(cls);
        }
        return "";
      }};
}

/// One entry of labels.extra_classes, `{name: NAME, ids: [ID, …]}`; returns an error text ("" on success).
std::string readExtraClass(const YAML::Node& n, ExtraClass* out) {
  if (!n.IsMap()) return "expected a map {name: NAME, ids: [ID, ...]}";
  bool has_name = false;
  for (const auto& kv : n) {
    const std::string key = scalarText(kv.first);
    if (key == "name") {
      if (!kv.second.IsScalar()) return "name: expected a class name";
      out->name = kv.second.Scalar();
      has_name = true;
    } else if (key == "ids") {
      if (!kv.second.IsSequence()) return "ids: expected a list of raw ids, e.g. [10, 252]";
      const std::string err = readIds(kv.second, &out->ids);
      if (!err.empty()) return err;
    } else {
      return "unknown key " + quoteContent(key) + " (expected name and ids)";
    }
  }
  return has_name ? "" : "missing name";
}

Field extraClasses(const Setting& setting) {
  return Field{
      setting.key, setting.comment(),
      [](const Config& c) {
        std::string s = "[";
        for (const ExtraClass& e : c.labels.extra_classes) {
          s += (s.size() > 1 ? ", " : "") + std::string("{name: ") + e.name + ", ids: " + idsText(e.ids) + "}";
        }
        return s + "]";
      },
      [](Config& c, const YAML::Node& n) -> std::string {
        if (!n.IsSequence() && !n.IsNull()) return "expected a list of {name: NAME, ids: [ID, ...]}";
        c.labels.extra_classes.clear();
        if (n.IsNull()) return "";
        for (size_t k = 0; k < n.size(); ++k) {
          ExtraClass extra;
          const std::string err = readExtraClass(n[k], &extra);
          if (!err.empty()) return "entry " + std::to_string(k) + ": " + err;
          c.labels.extra_classes.push_back(std::move(extra));
        }
        return "";
      }};
}

/// association.entries as the letters of the kept vertices, e.g. "ijk" or "ik".
Field entriesField(const Setting& setting) {
  return Field{setting.key, setting.comment(),
               [](const Config& c) {
                 std::string s;
                 for (int v = 0; v < 3; ++v) {
                   if (c.association.entries & (1u << v)) s += "ijk"[v];
                 }
                 return s;
               },
               [](Config& c, const YAML::Node& n) -> std::string {
                 const std::string s = scalarText(n);
                 unsigned mask = 0;
                 for (char ch : s) {
                   const size_t v = std::string("ijk").find(ch);
                   if (v == std::string::npos || (mask & (1u << v))) return "expected distinct letters from i, j, k";
                   mask |= 1u << v;
                 }
                 if (mask == 0) return "expected distinct letters from i, j, k";
                 c.association.entries = mask;
                 return "";
               }};
}

}  // namespace

std::vector<Field> fieldsFor(const LabelConfig& labels) {
  std::vector<Field> fields;
  for (const Setting& s : settingsFor(labels)) {
    if (s.type != SettingType::kCustom) {
      fields.push_back(fieldOf(s));
    } else if (s.key == "labels.custom_map") {
      fields.push_back(customMap(s));
    } else if (s.key == "labels.extra_classes") {
      fields.push_back(extraClasses(s));
    } else if (s.key == "association.entries") {
      fields.push_back(entriesField(s));
    } else {
      throw std::logic_error("config_fields.cpp has no reader for the custom setting " + s.key);
    }
  }
  return fields;
}

}  // namespace sgtllc::io::detail
