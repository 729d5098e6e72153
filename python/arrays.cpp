#include "arrays.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>

#include <Python.h>

#include "sgtllc/io/trajectory.h"

namespace sgtllc::python {
namespace {

py::array asArray(const py::handle& obj) {
  if (py::isinstance<py::array>(obj)) return py::reinterpret_borrow<py::array>(obj);
  return py::module_::import("numpy").attr("asarray")(obj);
}

/// What was passed instead, for "expected ..., got ...": `shape (3, 2)`, or `None` (numpy.asarray(None) is a
/// 0-d object array, whose shape () would say nothing).
std::string shapeText(const py::array& a) {
  if (a.ndim() == 0 && a.dtype().kind() == 'O' && a.attr("item")().is_none()) return "None";
  std::string s = "shape (";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += (d ? ", " : "") + std::to_string(a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string dtypeText(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

[[noreturn]] void fail(const std::string& message) { throw py::value_error(message); }

/// The array as C-contiguous T, converting a float (or, for integers, integer) dtype of another size.
template <class T>
py::array_t<T, py::array::c_style> contiguous(const py::array& a) {
  return py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
}

char kindOf(const py::array& a) { return a.dtype().kind(); }

void requireFloat(const py::array& a, const std::string& name, const std::string& expected) {
  if (kindOf(a) != 'f') fail(name + ": expected " + expected + " float array, got dtype " + dtypeText(a));
}

}  // namespace

std::vector<Eigen::Vector3f> pointsFromArray(const py::handle& obj, const char* name, bool drop_nonfinite) {
  const py::array a = asArray(obj);
  const std::string expected = "an (N, 3) or (N, 4)";
  if (a.ndim() != 2 || (a.shape(1) != 3 && a.shape(1) != 4)) {
    fail(std::string(name) + ": expected " + expected + " float array, got " + shapeText(a));
  }
  requireFloat(a, name, expected);
  const auto n = static_cast<size_t>(a.shape(0));
  const size_t cols = static_cast<size_t>(a.shape(1));
  std::vector<Eigen::Vector3f> points(n);
  static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "Vector3f must be three packed floats");
  const auto f = contiguous<float>(a);
  const float* src = f.data();
  if (cols == 3) {
    if (n) std::memcpy(points.front().data(), src, n * sizeof(Eigen::Vector3f));
  } else {
    for (size_t i = 0; i < n; ++i) points[i] = Eigen::Vector3f(src[4 * i], src[4 * i + 1], src[4 * i + 2]);
  }
  if (!drop_nonfinite) {
    for (size_t i = 0; i < n; ++i) {
      if (!points[i].allFinite()) {
        fail(std::string(name) + "[" + std::to_string(i) + "] is not finite (NaN or Inf); remove such points or " +
             "pass drop_nonfinite=True to let the detector drop and count them");
      }
    }
  }
  return points;
}

std::vector<uint32_t> labelsFromArray(const py::handle& obj, const char* name, size_t expected_size) {
  const py::array a = asArray(obj);
  const std::string expected = "an (N,) integer array of raw label ids, N = " + std::to_string(expected_size);
  if (a.ndim() != 1 || static_cast<size_t>(a.shape(0)) != expected_size) {
    fail(std::string(name) + ": expected " + expected + ", got " + shapeText(a));
  }
  const char kind = kindOf(a);
  if (kind != 'i' && kind != 'u') fail(std::string(name) + ": expected " + expected + ", got dtype " + dtypeText(a));
  std::vector<uint32_t> labels(expected_size);
  if (kind == 'u' && a.itemsize() == 4) {
    const auto u = contiguous<uint32_t>(a);
    if (expected_size) std::memcpy(labels.data(), u.data(), expected_size * sizeof(uint32_t));
    return labels;
  }
  const auto range_error = [&](size_t i, const std::string& value) {
    fail(std::string(name) + "[" + std::to_string(i) + "] = " + value + " is not a raw id in 0..4294967295");
  };
  if (kind == 'u') {
    const auto u = contiguous<uint64_t>(a);
    for (size_t i = 0; i < expected_size; ++i) {
      if (u.data()[i] > std::numeric_limits<uint32_t>::max()) range_error(i, std::to_string(u.data()[i]));
      labels[i] = static_cast<uint32_t>(u.data()[i]);
    }
  } else {
    const auto s = contiguous<int64_t>(a);
    for (size_t i = 0; i < expected_size; ++i) {
      const int64_t v = s.data()[i];
      if (v < 0 || v > static_cast<int64_t>(std::numeric_limits<uint32_t>::max())) range_error(i, std::to_string(v));
      labels[i] = static_cast<uint32_t>(v);
    }
  }
  return labels;
}

LabeledCloud cloudFromArrays(const py::handle& points, const py::handle& labels, const std::string& prefix,
                             bool drop_nonfinite) {
  LabeledCloud cloud;
  cloud.points = pointsFromArray(points, (prefix + "points").c_str(), drop_nonfinite);
  cloud.labels = labelsFromArray(labels, (prefix + "labels").c_str(), cloud.points.size());
  return cloud;
}

std::vector<Node> nodesFromArrays(const py::handle& centres, const py::handle& classes, const std::string& prefix,
                                  int num_classes) {
  const std::string cname = prefix + "centres", lname = prefix + "classes";
  const py::array c = asArray(centres);
  if (c.ndim() != 2 || c.shape(1) != 3) fail(cname + ": expected an (N, 3) float array, got " + shapeText(c));
  requireFloat(c, cname, "an (N, 3)");
  const auto n = static_cast<size_t>(c.shape(0));
  const py::array l = asArray(classes);
  const std::string expected = "an (N,) integer array of class indices, N = " + std::to_string(n);
  if (l.ndim() != 1 || static_cast<size_t>(l.shape(0)) != n) fail(lname + ": expected " + expected + ", got " + shapeText(l));
  if (kindOf(l) != 'i' && kindOf(l) != 'u') fail(lname + ": expected " + expected + ", got dtype " + dtypeText(l));
  const auto cd = contiguous<double>(c);
  const auto ld = contiguous<int64_t>(l);
  std::vector<Node> nodes(n);
  for (size_t i = 0; i < n; ++i) {
    nodes[i].centre = Eigen::Vector3d(cd.data()[3 * i], cd.data()[3 * i + 1], cd.data()[3 * i + 2]);
    if (!nodes[i].centre.allFinite()) fail(cname + "[" + std::to_string(i) + "] is not finite (NaN or Inf)");
    const int64_t v = ld.data()[i];
    if (v < 0 || v >= num_classes) {
      fail(lname + "[" + std::to_string(i) + "] = " + std::to_string(v) + " is not a class index 0.." +
           std::to_string(num_classes - 1) + " (the configuration has " + std::to_string(num_classes) + " classes)");
    }
    nodes[i].label = static_cast<int>(v);
  }
  return nodes;
}

py::tuple nodesToArrays(const std::vector<Node>& nodes) {
  const auto n = static_cast<py::ssize_t>(nodes.size());
  py::array_t<double> centres({n, py::ssize_t{3}});
  py::array_t<int32_t> classes(n);
  auto c = centres.mutable_unchecked<2>();
  auto l = classes.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) c(i, k) = nodes[i].centre[k];
    l(i) = nodes[i].label;
  }
  return py::make_tuple(centres, classes);
}

Eigen::MatrixXd matrixFromArray(const py::handle& obj, const char* name, int rows, int cols) {
  const py::array a = asArray(obj);
  const std::string expected = "a (" + std::to_string(rows) + ", " + std::to_string(cols) + ") float array";
  if (a.ndim() != 2 || a.shape(0) != rows || a.shape(1) != cols) {
    fail(std::string(name) + ": expected " + expected + ", got " + shapeText(a));
  }
  if (kindOf(a) != 'f' && kindOf(a) != 'i') fail(std::string(name) + ": expected " + expected + ", got dtype " + dtypeText(a));
  const auto d = contiguous<double>(a);
  Eigen::MatrixXd m(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) m(r, c) = d.data()[r * cols + c];
  if (!m.allFinite()) fail(std::string(name) + ": not finite (NaN or Inf)");
  return m;
}

Eigen::Isometry3d isometryFromArray(const py::handle& obj, const char* name) {
  const Eigen::Matrix4d T = matrixFromArray(obj, name, 4, 4);
  if (!T.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1))) fail(std::string(name) + ": the last row must be 0 0 0 1");
  Eigen::Isometry3d iso;
  iso.matrix() = T;
  return iso;
}

std::vector<Eigen::Matrix4d> posesFromArray(const py::handle& obj, const char* name) {
  const py::array a = asArray(obj);
  if (a.ndim() != 3 || a.shape(1) != 4 || a.shape(2) != 4) {
    fail(std::string(name) + ": expected an (N, 4, 4) float array, got " + shapeText(a));
  }
  if (kindOf(a) != 'f') fail(std::string(name) + ": expected an (N, 4, 4) float array, got dtype " + dtypeText(a));
  const auto d = contiguous<double>(a);
  std::vector<Eigen::Matrix4d> poses(static_cast<size_t>(a.shape(0)));
  for (size_t i = 0; i < poses.size(); ++i) {
    poses[i] = Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(d.data() + 16 * i);
    if (!poses[i].allFinite()) fail(std::string(name) + "[" + std::to_string(i) + "] is not finite (NaN or Inf)");
  }
  return poses;
}

std::vector<Eigen::Matrix4d> rigidPosesFromArray(const py::handle& obj, const char* name) {
  std::vector<Eigen::Matrix4d> poses = posesFromArray(obj, name);
  for (size_t i = 0; i < poses.size(); ++i) {
    const std::string at = std::string(name) + "[" + std::to_string(i) + "]";
    io::checkRotation(poses[i].topLeftCorner<3, 3>(), at);
    if (poses[i].row(3) != Eigen::RowVector4d(0, 0, 0, 1)) throw Error(at + ": the last row must be 0 0 0 1");
  }
  return poses;
}

std::vector<Eigen::Isometry3d> isometriesFromArray(const py::handle& obj, const char* name) {
  std::vector<Eigen::Isometry3d> out;
  for (const Eigen::Matrix4d& T : posesFromArray(obj, name)) out.emplace_back(T);
  return out;
}

std::vector<double> doublesFromArray(const py::handle& obj, const char* name) {
  const py::array a = asArray(obj);
  if (a.ndim() != 1) fail(std::string(name) + ": expected an (N,) array, got " + shapeText(a));
  const char kind = kindOf(a);
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b') {
    fail(std::string(name) + ": expected an (N,) numeric array, got dtype " + dtypeText(a));
  }
  const auto d = contiguous<double>(a);
  std::vector<double> v(d.data(), d.data() + d.size());
  for (size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) fail(std::string(name) + "[" + std::to_string(i) + "] is not finite (NaN or Inf)");
  }
  return v;
}

py::array_t<double> posesToArray(const std::vector<Eigen::Matrix4d>& poses) {
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto o = out.mutable_unchecked<3>();
  for (size_t i = 0; i < poses.size(); ++i)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) o(static_cast<py::ssize_t>(i), r, c) = poses[i](r, c);
  return out;
}

py::array_t<double> posesToArray(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Matrix4d> m;
  m.reserve(poses.size());
  for (const Eigen::Isometry3d& p : poses) m.push_back(p.matrix());
  return posesToArray(m);
}

py::array_t<double> matrixToArray(const Eigen::Matrix4d& T) {
  py::array_t<double> out({py::ssize_t{4}, py::ssize_t{4}});
  auto o = out.mutable_unchecked<2>();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) o(r, c) = T(r, c);
  return out;
}

py::array_t<float> pointsToArray(std::vector<Eigen::Vector3f>&& points) {
  const auto n = static_cast<py::ssize_t>(points.size());
  auto* owner = new std::vector<Eigen::Vector3f>(std::move(points));
  py::capsule free_when_done(owner, [](void* p) { delete static_cast<std::vector<Eigen::Vector3f>*>(p); });
  return py::array_t<float>({n, py::ssize_t{3}}, reinterpret_cast<float*>(owner->data()), free_when_done);
}

void requireFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    PyErr_SetString(PyExc_FileNotFoundError, ("no such file: " + path).c_str());
    throw py::error_already_set();
  }
}

}  // namespace sgtllc::python
