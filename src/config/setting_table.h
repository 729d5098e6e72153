// Private to the core: how the settings tables (settings_*.cpp) declare a section's settings, one line each.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "sgtllc/config.h"
#include "sgtllc/config/settings.h"

namespace sgtllc::detail {

/// "[0, 1]", "(0, 1000]", "[0, 20)", or "0 (MEANING) or [LO, HI]" as a SettingRange; a malformed text is a
/// programming error (std::logic_error at the first use of the table).
SettingRange parseRange(const std::string& text);

/// The settings of one struct S of Config, under the key prefix "PREFIX.".
template <class S>
class SectionTable {
 public:
  SectionTable(std::string prefix, std::function<S&(Config&)> of, std::vector<Setting>* out)
      : prefix_(std::move(prefix)), of_(std::move(of)), out_(out) {}

  /// A double, int or uint32 member with its range ("[0, 1]") and unit ("" for counts and shares).
  template <class T>
  void number(const char* name, T S::*member, const std::string& range, const char* unit, const char* meaning) {
    numberIn(name, member, parseRange(range), unit, meaning);
  }

  /// A number whose range depends on other settings, checked by Config::validate's own rules; @p note says how.
  template <class T>
  void ruledNumber(const char* name, T S::*member, const char* note, const char* unit, const char* meaning) {
    SettingRange range;
    range.checked = false;
    range.note = note;
    numberIn(name, member, range, unit, meaning);
  }

  void flag(const char* name, bool S::*member, const char* meaning) {
    Setting s = base(name, SettingType::kFlag, meaning, "", typeid(bool));
    s.get = [member](const void* x) { return static_cast<const S*>(x)->*member ? 1.0 : 0.0; };
    s.set = [member](void* x, double v) { static_cast<S*>(x)->*member = v != 0.0; };
    out_->push_back(std::move(s));
  }

  /// An enum member and its YAML names, in the order `sgtllc config` lists them.
  template <class E>
  void choice(const char* name, E S::*member, const std::vector<std::pair<const char*, E>>& names,
              const char* meaning) {
    Setting s = base(name, SettingType::kChoice, meaning, "", typeid(E));
    for (const auto& [text, value] : names) s.choices.emplace_back(text, static_cast<int>(value));
    s.get = [member](const void* x) { return static_cast<double>(static_cast<int>(static_cast<const S*>(x)->*member)); };
    s.set = [member](void* x, double v) { static_cast<S*>(x)->*member = static_cast<E>(static_cast<int>(v)); };
    out_->push_back(std::move(s));
  }

  void ids(const char* name, std::vector<uint32_t> S::*member, const char* meaning) {
    Setting s = base(name, SettingType::kIdList, meaning, "", typeid(std::vector<uint32_t>));
    s.ids = [member](void* x) { return &(static_cast<S*>(x)->*member); };
    out_->push_back(std::move(s));
  }

  /// A setting with a syntax of its own, which the YAML reader and the Python bindings handle by key.
  void custom(const char* name, const char* meaning) {
    out_->push_back(base(name, SettingType::kCustom, meaning, "", typeid(void)));
  }

 private:
  template <class T>
  void numberIn(const char* name, T S::*member, SettingRange range, const char* unit, const char* meaning) {
    Setting s = base(name, std::is_floating_point<T>::value ? SettingType::kReal : SettingType::kInteger, meaning,
                     unit, typeid(T));
    s.range = std::move(range);
    if (!std::is_floating_point<T>::value) {
      s.storage_lo = static_cast<double>(std::numeric_limits<T>::min());
      s.storage_hi = static_cast<double>(std::numeric_limits<T>::max());
    }
    s.get = [member](const void* x) { return static_cast<double>(static_cast<const S*>(x)->*member); };
    s.set = [member](void* x, double v) { static_cast<S*>(x)->*member = static_cast<T>(v); };
    out_->push_back(std::move(s));
  }

  Setting base(const char* name, SettingType type, const char* meaning, const char* unit, const std::type_info& t) {
    Setting s;
    s.key = prefix_.empty() ? name : prefix_ + "." + name;
    s.name = name;
    s.type = type;
    s.meaning = meaning;
    s.unit = unit;
    s.section = typeid(S);
    s.value_type = t;
    s.section_of = [of = of_](Config& c) -> void* { return &of(c); };
    return s;
  }

  std::string prefix_;
  std::function<S&(Config&)> of_;
  std::vector<Setting>* out_;
};

// One function per table file, each appending its sections' settings in `sgtllc config` order.
void addLabelSettings(std::vector<Setting>* out);                         // settings_stages.cpp
void addClusterSettings(const LabelConfig& labels, std::vector<Setting>* out);  // settings_stages.cpp
void addStageSettings(std::vector<Setting>* out);       // settings_stages.cpp: graph … association
void addVerificationSettings(std::vector<Setting>* out);  // settings_verification.cpp
void addLabellerSettings(std::vector<Setting>* out);    // settings_labeller.cpp
void addRegistrationSettings(std::vector<Setting>* out);  // settings_registration.cpp
void addBackendSettings(std::vector<Setting>* out);     // settings_backend.cpp

}  // namespace sgtllc::detail
