// A clear TypeError for an attribute given a value of the wrong type. pybind11's setters of def_readwrite raise
// "incompatible function arguments" with a signature dump; the attribute's name and expected type are what the
// user needs ("GraphConfig.sigma_d: expected float, got str 'a'"). One pass over the module's classes after they
// are bound rewraps every writable property, so a new field needs no code of its own.
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"

namespace sgtllc::python {
namespace {

/// The value type from a pybind11 setter's signature "(self: sgtllc.GraphConfig, arg0: float) -> None" or
/// "(arg0: sgtllc.GraphConfig, arg1: float) -> None".
std::string expectedType(const py::object& fset) {
  const std::string doc = py::str(fset.attr("__doc__"));
  // def_readwrite's setters take (self, arg0); the settings table's lambdas (settings.h) take (arg0, arg1).
  size_t from = doc.find(", arg1: ");
  from = from == std::string::npos ? doc.find("arg0: ") : from + 2;
  const size_t to = doc.find(") -> None");
  if (from == std::string::npos || to == std::string::npos || to <= from) return "a value of the attribute's type";
  return doc.substr(from + 6, to - from - 6);
}

std::string shortRepr(const py::handle& value) {
  std::string r = py::repr(value);
  if (r.size() > 40) r = r.substr(0, 37) + "...";
  return r;
}

py::object explainingSetter(py::object fset, std::string attribute, std::string expected) {
  return py::cpp_function([fset = std::move(fset), attribute = std::move(attribute),
                           expected = std::move(expected)](const py::object& self, const py::object& value) {
    try {
      fset(self, value);
    } catch (py::error_already_set& e) {
      // Only pybind11's argument mismatch: a setter's own TypeError (if any) already says what it means.
      const bool mismatch = std::string(e.what()).find("incompatible function arguments") != std::string::npos;
      if (!e.matches(PyExc_TypeError) || !mismatch) throw;
      throw py::type_error(attribute + ": expected " + expected + ", got " +
                           py::str(py::type::of(value).attr("__name__")).cast<std::string>() + " " +
                           shortRepr(value));
    }
  });
}

}  // namespace

void explainSetterTypeErrors(py::module_& m) {
  const py::object property = py::module_::import("builtins").attr("property");
  for (const auto& entry : py::reinterpret_borrow<py::dict>(m.attr("__dict__"))) {
    if (!py::isinstance<py::type>(entry.second)) continue;
    const py::object cls = py::reinterpret_borrow<py::object>(entry.second);
    const std::string class_name = py::str(cls.attr("__name__"));
    std::vector<std::pair<std::string, py::object>> replaced;
    for (const py::handle item : cls.attr("__dict__").attr("items")()) {
      const py::tuple kv = py::reinterpret_borrow<py::tuple>(item);
      const py::object prop = kv[1];
      if (!py::isinstance(prop, property) || prop.attr("fset").is_none()) continue;
      const std::string name = py::str(kv[0]);
      const py::object fset = prop.attr("fset");
      replaced.emplace_back(name, property(prop.attr("fget"), explainingSetter(fset, class_name + "." + name,
                                                                               expectedType(fset)),
                                           py::none(), prop.attr("__doc__")));
    }
    for (const auto& [name, prop] : replaced) py::setattr(cls, name.c_str(), prop);
  }
}

}  // namespace sgtllc::python
