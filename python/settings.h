// Private to the Python module: the properties of the config classes come from the settings table
// (sgtllc/config/settings.h), one per setting, typed as the setting is, with its meaning, unit and range as the
// docstring. A setting added to the table appears here without a line of its own.
#pragma once

#include <deque>
#include <string>
#include <typeindex>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "sgtllc/config/settings.h"

namespace sgtllc::python {

/// Makes @p enum_type the Python type of the choice settings whose enum is @p type.
void registerChoiceEnum(std::type_index type, py::handle enum_type);
/// The member of the registered enum for @p type with the value @p v.
py::object choiceValue(const Setting& setting, int v);
/// The enum value of @p value, which must be a member of the registered enum (TypeError naming @p attribute if not).
int choiceFromPython(const Setting& setting, const py::handle& value, const std::string& attribute);
/// The docstring of a setting's property: its meaning, unit and range.
std::string settingDoc(const Setting& setting);

/// py::enum_<E> as usual, registered for the choice settings of type E.
template <class E>
py::enum_<E> choiceEnum(py::module_& m, const char* name, const char* doc) {
  py::enum_<E> e(m, name, doc);
  registerChoiceEnum(typeid(E), e);
  return e;
}

/// The Python class of the config section S, with one property per setting it holds (the settings with a syntax
/// of their own are bound by hand, as is the constructor).
template <class S>
py::class_<S> settingsClass(py::module_& m, const char* class_name, const char* class_doc) {
  py::class_<S> cls(m, class_name, class_doc);
  // Static: the properties' closures and docstrings refer to the table for the life of the module.
  static const std::vector<Setting> table = settingsOfSection(typeid(S));
  static std::deque<std::string> docs;  // a deque keeps each string where it is
  for (const Setting& s : table) {
    const std::string attribute = std::string(class_name) + "." + s.name;
    const char* doc = docs.emplace_back(settingDoc(s)).c_str();
    switch (s.type) {
      case SettingType::kReal:
        cls.def_property(s.name.c_str(), [&s](const S& x) { return s.get(&x); },
                         [&s](S& x, double v) { s.set(&x, v); }, doc);
        break;
      case SettingType::kInteger:
        cls.def_property(s.name.c_str(), [&s](const S& x) { return static_cast<long long>(s.get(&x)); },
                         [&s, attribute](S& x, long long v) {
                           if (v < s.storage_lo || v > s.storage_hi) {
                             throw py::type_error(attribute + ": expected an integer in " +
                                                  std::to_string(static_cast<long long>(s.storage_lo)) + ".." +
                                                  std::to_string(static_cast<long long>(s.storage_hi)) + ", got " +
                                                  std::to_string(v));
                           }
                           s.set(&x, static_cast<double>(v));
                         },
                         doc);
        break;
      case SettingType::kFlag:
        cls.def_property(s.name.c_str(), [&s](const S& x) { return s.get(&x) != 0.0; },
                         [&s](S& x, bool v) { s.set(&x, v ? 1.0 : 0.0); }, doc);
        break;
      case SettingType::kChoice:
        cls.def_property(s.name.c_str(), [&s](const S& x) { return choiceValue(s, static_cast<int>(s.get(&x))); },
                         [&s, attribute](S& x, const py::object& v) { s.set(&x, choiceFromPython(s, v, attribute)); },
                         doc);
        break;
      case SettingType::kIdList:
        // A tuple, as ExtraClass.ids: `ids.append(…)` would change a copy; assign a new list instead.
        cls.def_property(s.name.c_str(), [&s](S& x) { return py::tuple(py::cast(*s.ids(&x))); },
                         [&s](S& x, std::vector<uint32_t> v) { *s.ids(&x) = std::move(v); }, doc);
        break;
      case SettingType::kCustom:
        break;
    }
  }
  return cls;
}

}  // namespace sgtllc::python
