/// @file settings.h
/// @brief The settings table: every key of sgtllc::Config declared once, with its member, type, range, unit and
///        one line of meaning.
///
/// The table drives everything that speaks of settings: Config::validate() (one rule set, one message format:
/// "KEY = VALUE is out of range RANGE"), the YAML reader and writer (sgtllc/io/config_yaml.h), the Python
/// properties of the config classes and their stub, `sgtllc config --markdown` (docs/configuration.md) and the
/// range tests. Adding a setting is one line in a table (src/config/settings_*.cpp) plus the code that reads it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <typeindex>
#include <utility>
#include <vector>

namespace sgtllc {

struct Config;
struct LabelConfig;

/// What a setting holds, and so how YAML and Python spell it.
enum class SettingType {
  kReal,     ///< a finite double
  kInteger,  ///< an integer (int or uint32 member)
  kFlag,     ///< true or false
  kChoice,   ///< one of the named values of an enum
  kIdList,   ///< a list of raw label ids 0..65535
  kCustom,   ///< a value with its own syntax (labels.custom_map, labels.extra_classes, association.entries)
};

/// The values a numeric setting accepts: an interval, and optionally 0 beside it ("0 (off) or [0.001, 10]").
struct SettingRange {
  double lo = 0.0, hi = 0.0;
  bool lo_open = false, hi_open = false;
  /// Besides the interval, 0 is accepted and means this ("no downsampling"); empty: 0 is not special.
  std::string zero_means;
  /// false: the range depends on other settings and is checked by Config::validate's own rules; `note` says how.
  bool checked = true;
  std::string note;  ///< the range in words when it is not a plain interval (checked = false)

  bool accepts(double v) const;
  /// "[0, 1]", "(0, 1000]", "0 (no downsampling) or [0.001, 10]", or the note.
  std::string text() const;
};

/// One setting of the table. Its value lives in a struct of Config (the section: VerificationConfig, …); the
/// accessors reach it from a Config or from the section itself (what the Python properties need).
struct Setting {
  std::string key;      ///< dotted YAML key, e.g. "verification.sigma_4"
  std::string name;     ///< the member's name, the key's last part
  SettingType type = SettingType::kReal;
  std::string meaning;  ///< one line
  std::string unit;     ///< "m", "deg", "rad/m", …; empty for counts, shares and flags
  SettingRange range;   ///< kReal and kInteger
  double storage_lo = 0.0, storage_hi = 0.0;  ///< kInteger: what the member's type holds
  std::vector<std::pair<std::string, int>> choices;  ///< kChoice: YAML name → the enum's value, in order
  std::type_index section = typeid(void);  ///< the struct holding the member
  std::type_index value_type = typeid(void);  ///< the member's type (the enum of a choice)

  std::function<void*(Config&)> section_of;               ///< the section within a Config
  std::function<double(const void* section)> get;         ///< kReal, kInteger, kFlag (0/1), kChoice (enum value)
  std::function<void(void* section, double)> set;         ///< the same kinds
  std::function<std::vector<uint32_t>*(void* section)> ids;  ///< kIdList

  /// The value in @p config (numeric kinds: a double holds every int and uint32 exactly).
  double value(const Config& config) const;
  void assign(Config& config, double v) const;
  std::vector<uint32_t>& idList(Config& config) const;
  /// The YAML name of a choice's enum value @p v; "?" for a value with no name.
  std::string choiceName(int v) const;
  /// The meaning, with the unit and a choice's names: what `sgtllc config` prints beside the key.
  std::string comment() const;
};

/// Every setting, in `sgtllc config` order, for the class set of @p labels (one cluster.NAME section per class).
std::vector<Setting> settingsFor(const LabelConfig& labels);
/// The settings whose values live in a struct of type @p section, once each (cluster.NAME's members once).
std::vector<Setting> settingsOfSection(std::type_index section);

/// Throws ConfigError for the first setting in @p config outside its range ("KEY = VALUE is out of range RANGE");
/// only keys starting with @p prefix ("" = all). Config::validate() adds the rules that tie settings together.
void checkSettingRanges(const Config& config, const std::string& prefix = "");

}  // namespace sgtllc
