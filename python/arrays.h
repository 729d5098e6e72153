// Private to the Python module: numpy arrays in and out of the library's value types.
//
// Inputs are checked here, before the GIL is released, so that a wrong shape, dtype or value is a ValueError
// that names the argument and the expected shape, never a crash inside the library. The library takes its own
// containers (LabeledCloud, std::vector<Node>), so an input is copied once; an (N, 3) float32 C-contiguous array is
// copied with one memcpy, other layouts and dtypes are converted on the way. Outputs that the library returns as
// a std::vector are handed to numpy without a copy (the array owns the vector).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "sgtllc/types.h"

namespace sgtllc::python {

namespace py = pybind11;

/// An argument that numpy.asarray accepts (an array, a nested list, ...), taken as it is and checked by the
/// *FromArray functions below, so a wrong shape is their ValueError rather than pybind11's TypeError. Signatures
/// show it as numpy.typing.ArrayLike.
struct ArrayLike {
  py::object object;
  operator py::handle() const { return object; }  // NOLINT: used where a py::handle is expected
};

/// (N, 3) or (N, 4) float32/float64 points (a 4th column, e.g. intensity, is ignored). With @p drop_nonfinite
/// false a NaN or Inf coordinate is a ValueError; with true such points are passed on, and the library drops and
/// counts them (ExtractionStats::nonfinite_points), as the command-line tool does.
std::vector<Eigen::Vector3f> pointsFromArray(const py::handle& points, const char* name, bool drop_nonfinite);

/// (N,) integer raw ids 0..2³²−1 (uint32 is taken as it is; other integer dtypes are range-checked).
std::vector<uint32_t> labelsFromArray(const py::handle& labels, const char* name, size_t expected_size);

/// A labelled scan from the two arrays; names "points"/"labels" prefixed with @p prefix ("query_", "match_").
LabeledCloud cloudFromArrays(const py::handle& points, const py::handle& labels, const std::string& prefix,
                             bool drop_nonfinite);

/// Nodes from (N, 3) finite float centres and (N,) integer classes in 0..num_classes−1.
std::vector<Node> nodesFromArrays(const py::handle& centres, const py::handle& classes, const std::string& prefix,
                                  int num_classes);

/// (centres (N, 3) float64, classes (N,) int32) of @p nodes.
py::tuple nodesToArrays(const std::vector<Node>& nodes);

/// A (rows, cols) finite float64 matrix, e.g. a (4, 4) pose.
Eigen::MatrixXd matrixFromArray(const py::handle& array, const char* name, int rows, int cols);
/// A (4, 4) rigid transform (the last row must be 0 0 0 1).
Eigen::Isometry3d isometryFromArray(const py::handle& array, const char* name);
/// (N, 4, 4) finite float64 poses.
std::vector<Eigen::Matrix4d> posesFromArray(const py::handle& array, const char* name);
std::vector<Eigen::Isometry3d> isometriesFromArray(const py::handle& array, const char* name);
/// posesFromArray, each pose rigid as a trajectory file's must be (io::checkRotation, last row 0 0 0 1): else
/// sgtllc.Error `NAME[i]: rotation is not orthonormal (...)`, the command line's message.
std::vector<Eigen::Matrix4d> rigidPosesFromArray(const py::handle& array, const char* name);
/// (N,) float64 values.
std::vector<double> doublesFromArray(const py::handle& array, const char* name);

/// (N, 4, 4) float64 of @p poses.
py::array_t<double> posesToArray(const std::vector<Eigen::Matrix4d>& poses);
py::array_t<double> posesToArray(const std::vector<Eigen::Isometry3d>& poses);
/// (4, 4) float64 copy of @p T.
py::array_t<double> matrixToArray(const Eigen::Matrix4d& T);

/// Moves @p values into a numpy array of @p shape without copying them (the array owns the vector).
template <class T>
py::array_t<T> vectorToArray(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owner = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(std::move(shape), owner->data(), free_when_done);
}

/// (N, 3) float32 of @p points without copying them.
py::array_t<float> pointsToArray(std::vector<Eigen::Vector3f>&& points);

/// Raises FileNotFoundError naming @p path if it does not exist (the library's "cannot open" is a ValueError).
void requireFile(const std::string& path);

}  // namespace sgtllc::python

namespace pybind11::detail {
template <>
struct type_caster<sgtllc::python::ArrayLike> {
  PYBIND11_TYPE_CASTER(sgtllc::python::ArrayLike, const_name("numpy.typing.ArrayLike"));
  bool load(handle src, bool) {
    value.object = reinterpret_borrow<object>(src);
    return true;
  }
  static handle cast(const sgtllc::python::ArrayLike& v, return_value_policy, handle) { return v.object.inc_ref(); }
};
}  // namespace pybind11::detail
