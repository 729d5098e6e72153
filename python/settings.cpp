// The settings table's properties (settings.h): the enums of the choice settings, and the docstrings.
#include "settings.h"

#include <map>

namespace sgtllc::python {
namespace {

/// The Python enum type of each choice setting's C++ enum. Borrowed handles with a reference held: the types live
/// as long as the module, and no destructor may run after the interpreter has gone.
std::map<std::type_index, PyObject*>& choiceEnums() {
  static auto* enums = new std::map<std::type_index, PyObject*>();
  return *enums;
}

py::handle enumOf(const Setting& setting) {
  const auto it = choiceEnums().find(setting.value_type);
  if (it == choiceEnums().end()) throw std::logic_error("no Python enum registered for the setting " + setting.key);
  return it->second;
}

}  // namespace

void registerChoiceEnum(std::type_index type, py::handle enum_type) { choiceEnums()[type] = enum_type.inc_ref().ptr(); }

py::object choiceValue(const Setting& setting, int v) { return enumOf(setting)(v); }

int choiceFromPython(const Setting& setting, const py::handle& value, const std::string& attribute) {
  const py::handle type = enumOf(setting);
  if (!py::isinstance(value, type)) {
    const std::string expected =
        py::str(type.attr("__module__")).cast<std::string>() + "." + py::str(type.attr("__name__")).cast<std::string>();
    throw py::type_error(attribute + ": expected " + expected + ", got " +
                         py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                         py::repr(value).cast<std::string>());
  }
  return value.attr("value").cast<int>();
}

std::string settingDoc(const Setting& setting) {
  std::string doc = setting.comment();
  if (setting.type == SettingType::kReal || setting.type == SettingType::kInteger) {
    SettingRange interval = setting.range;  // the comment already says what 0 means
    interval.zero_means.clear();
    doc += std::string(", ") + (setting.range.checked ? "in " : "") + (setting.range.zero_means.empty() ? "" : "0 or ") +
           interval.text();
  }
  return doc + " (YAML " + setting.key + ")";
}

}  // namespace sgtllc::python
