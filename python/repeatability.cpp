// Node repeatability and label agreement (include/sgtllc/eval/node_repeatability.h, label_agreement.h), as
// `sgtllc repeatability` measures them (docs/labeller.md §5).
#include <pybind11/stl.h>

#include <array>
#include <cmath>

#include "arrays.h"
#include "bindings.h"
#include "sgtllc/eval/label_agreement.h"
#include "sgtllc/eval/node_repeatability.h"

namespace sgtllc::python {
namespace {

template <class T>
py::array_t<int64_t> perClass(const std::array<T, kMaxClasses>& counts) {
  std::vector<int64_t> v(counts.begin(), counts.end());
  return vectorToArray(std::move(v), {kMaxClasses});
}

/// (N,) stable classes 0..kMaxClasses−1 or −1, as label_scan gives them.
std::vector<int8_t> classesFromArray(const py::handle& array, const char* name) {
  const std::vector<double> v = doublesFromArray(array, name);
  std::vector<int8_t> out(v.size());
  for (size_t i = 0; i < v.size(); ++i) {
    if (!(v[i] >= -1 && v[i] < kMaxClasses) || v[i] != std::floor(v[i])) {
      throw py::value_error(std::string(name) + ": expected stable classes 0.." + std::to_string(kMaxClasses - 1) +
                            " or -1 (dropped), got " + std::to_string(v[i]) + " at index " + std::to_string(i));
    }
    out[i] = static_cast<int8_t>(v[i]);
  }
  return out;
}

}  // namespace

void bindRepeatability(py::module_& m) {
  using eval::NodeRepeatability;
  py::class_<NodeRepeatability>(m, "NodeRepeatability",
                                "Per-class node counts of node_repeatability (arrays of length 16, by class index).")
      .def_property_readonly("nodes", [](const NodeRepeatability& r) { return perClass(r.nodes); },
                             "nodes of both scans in their common view")
      .def_property_readonly("repeated", [](const NodeRepeatability& r) { return perClass(r.repeated); },
                             "of those, nodes with a same-class node of the other scan within the radius")
      .def_property_readonly("other_class", [](const NodeRepeatability& r) { return perClass(r.other_class); },
                             "nodes with only nodes of another class within the radius")
      .def("share", py::overload_cast<>(&NodeRepeatability::share, py::const_), "repeated / nodes, all classes")
      .def("share", py::overload_cast<int>(&NodeRepeatability::share, py::const_), py::arg("class_index"));
  m.def(
      "node_repeatability",
      [](const ArrayLike& centres_a, const ArrayLike& classes_a, const ArrayLike& centres_b, const ArrayLike& classes_b,
         const ArrayLike& T_b_a, double radius, double range) {
        const std::vector<Node> a = nodesFromArrays(centres_a, classes_a, "a_", kMaxClasses);
        const std::vector<Node> b = nodesFromArrays(centres_b, classes_b, "b_", kMaxClasses);
        if (!(radius > 0.0) || !(range >= 0.0)) throw py::value_error("radius must be > 0 and range >= 0 (m)");
        return eval::nodeRepeatability(a, b, isometryFromArray(T_b_a, "T_b_a"), {radius, range});
      },
      py::arg("a_centres"), py::arg("a_classes"), py::arg("b_centres"), py::arg("b_classes"), py::arg("T_b_a"),
      py::arg("radius") = 0.5, py::arg("range") = 40.0,
      "Share of two scans' nodes with a same-class node of the other scan within radius (m) once a is moved by\n"
      "T_b_a (p_b = T_b_a p_a); only nodes within range (m, horizontal; 0 = all) of both sensors count.");

  using eval::ClassAgreement;
  py::class_<ClassAgreement>(m, "ClassAgreement", "Per-class point counts of label_agreement (length 16 arrays).")
      .def_property_readonly("tp", [](const ClassAgreement& k) { return perClass(k.tp); })
      .def_property_readonly("fp", [](const ClassAgreement& k) { return perClass(k.fp); })
      .def_property_readonly("fn", [](const ClassAgreement& k) { return perClass(k.fn); })
      .def("precision", &ClassAgreement::precision, py::arg("class_index"))
      .def("recall", &ClassAgreement::recall, py::arg("class_index"))
      .def("iou", &ClassAgreement::iou, py::arg("class_index"));
  m.def(
      "label_agreement",
      [](const ArrayLike& predicted, const ArrayLike& reference, const LabelConfig& reference_labels) {
        const std::vector<int8_t> p = classesFromArray(predicted, "predicted");
        const std::vector<uint32_t> ids = labelsFromArray(reference, "reference", p.size());
        ClassAgreement k;
        k.add(p, eval::stableClasses(ids, LabelMap(reference_labels)), eval::labellerMerge(reference_labels));
        return k;
      },
      py::arg("predicted"), py::arg("reference"), py::arg("reference_labels") = LabelConfig{},
      "Per-class agreement of label_scan's classes (N,) with a reference labelling (N,) of raw ids in the\n"
      "convention of reference_labels (LabelConfig): trunk counts as pole, as `sgtllc repeatability` counts it.");
}

}  // namespace sgtllc::python
