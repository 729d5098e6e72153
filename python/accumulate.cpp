// Scan accumulation (include/sgtllc/accumulate/scan_accumulator.h): ScanAccumulator and merge_scans.
#include <pybind11/stl.h>

#include "arrays.h"
#include "bindings.h"
#include "sgtllc/accumulate/scan_accumulator.h"

namespace sgtllc::python {
namespace {

/// (points (N, 3) float32, labels (N,) uint32) of @p cloud, without copying.
py::tuple cloudToArrays(LabeledCloud&& cloud) {
  const auto n = static_cast<py::ssize_t>(cloud.labels.size());
  return py::make_tuple(pointsToArray(std::move(cloud.points)), vectorToArray(std::move(cloud.labels), {n}));
}

}  // namespace

void bindAccumulate(py::module_& m) {
  py::class_<ScanAccumulator>(m, "ScanAccumulator",
                              "A bounded buffer of the last N labelled scans with their poses; add() returns the new "
                              "scan merged with the N - 1 before it, in the new scan's frame.")
      .def(py::init<int>(), py::arg("scans"), "scans: N, 1..1000")
      .def(
          "add",
          [](ScanAccumulator& a, const ArrayLike& points, const ArrayLike& labels, const ArrayLike& T_world_scan) {
            LabeledCloud scan = cloudFromArrays(points, labels, "", /*drop_nonfinite=*/true);
            const Eigen::Isometry3d T = isometryFromArray(T_world_scan, "T_world_scan");
            LabeledCloud merged;
            {
              py::gil_scoped_release release;
              merged = a.add(std::move(scan), T);
            }
            return cloudToArrays(std::move(merged));
          },
          py::arg("points"), py::arg("labels"), py::arg("T_world_scan"),
          "Adds a scan ((N, 3|4) points, (N,) labels) taken at the (4, 4) pose T_world_scan; returns (points, "
          "labels) of the held scans, oldest first, moved into this scan's frame")
      .def_property_readonly("capacity", &ScanAccumulator::capacity, "N")
      .def("__len__", &ScanAccumulator::size, "scans held now (at most N)")
      .def_property_readonly("points", &ScanAccumulator::points, "points held now")
      .def_property_readonly("bytes", &ScanAccumulator::bytes, "bytes of the held points and labels (16 per point)")
      .def("clear", &ScanAccumulator::clear, "forgets every scan");
}

}  // namespace sgtllc::python
