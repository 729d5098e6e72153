// The `sgtllc` Python module (README "Python"): a thin mirror of the C++ library, numpy in and out.
//
// Exceptions: sgtllc::Error (bad input data or configuration) becomes sgtllc.Error, a ValueError; its subclass
// sgtllc::ConfigError becomes sgtllc.ConfigError, whose `key` attribute is the YAML key of the offending field
// (`verification.sigma_4`).
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "sgtllc/config.h"
#include "sgtllc/memory_reuse.h"

namespace py = pybind11;

namespace {

PyObject* g_error = nullptr;
PyObject* g_config_error = nullptr;

void translate(std::exception_ptr p) {
  try {
    if (p) std::rethrow_exception(p);
  } catch (const sgtllc::ConfigError& e) {
    py::object error = py::reinterpret_borrow<py::object>(g_config_error)(e.what());
    error.attr("key") = e.key();
    PyErr_SetObject(g_config_error, error.ptr());
  } catch (const sgtllc::Error& e) {
    PyErr_SetString(g_error, e.what());
  }
}

}  // namespace

PYBIND11_MODULE(sgtllc, m) {
  m.doc() =
      "sgtllc: LiDAR loop closing with semantic graphs (SGT-LLC), the Python mirror of the C++ library.\n\n"
      "Points are (N, 3) or (N, 4) float arrays in the sensor frame (metres), labels (N,) integer raw ids,\n"
      "poses (4, 4) float64 arrays; T_match_query maps query-frame points into the match frame.";
  g_error = PyErr_NewExceptionWithDoc("sgtllc.Error", "Bad input data or configuration (sgtllc::Error).",
                                      PyExc_ValueError, nullptr);
  g_config_error = PyErr_NewExceptionWithDoc(
      "sgtllc.ConfigError", "A configuration value out of range; `key` is its YAML key (sgtllc::ConfigError).",
      g_error, nullptr);
  m.attr("Error") = py::reinterpret_borrow<py::object>(g_error);
  m.attr("ConfigError") = py::reinterpret_borrow<py::object>(g_config_error);
  py::register_exception_translator(translate);

  m.attr("__version__") = SGTLLC_VERSION;
  sgtllc::python::bindLabel(m);  // before the Config that holds its types
  sgtllc::python::bindRegistration(m);  // before the Config and the results that hold its types
  sgtllc::python::bindConfig(m);
  sgtllc::python::bindBackendConfig(m);
  sgtllc::python::bindResults(m);
  sgtllc::python::bindMap(m);  // before the detector, whose to_map returns a Map
  sgtllc::python::bindDetector(m);
  sgtllc::python::bindIo(m);
  sgtllc::python::bindMetrics(m);
  sgtllc::python::bindRepeatability(m);
  sgtllc::python::bindRelocalization(m);
  sgtllc::python::bindBackend(m);
  sgtllc::python::bindAccumulate(m);
  sgtllc::python::bindPipeline(m);  // after the results, the back end and the map it returns
  sgtllc::python::bindSessions(m);  // after the pipeline, whose ClosingLoop it returns
  m.def("reuse_freed_memory", &sgtllc::reuseFreedMemory, py::arg("keep_bytes") = std::size_t{32} << 20,
        "Keeps up to keep_bytes of freed memory in the process for the next frame instead of handing it back to\n"
        "the system (glibc only; process-wide, so call it once, at start). Halves label_scan's time on a 120 k-point\n"
        "scan where page faults are slow; results do not change. False where the C library has no such setting.");
  m.def("huge_page_heap", &sgtllc::hugePageHeap, py::arg("bytes") = std::size_t{64} << 20,
        "Marks the next `bytes` of the heap for transparent huge pages: a page fault per 2 MB instead of per 4 KB\n"
        "(glibc and a kernel that offers them; process-wide, so call it once, at start, after reuse_freed_memory).\n"
        "Results do not change. False where the C library or the kernel has no such setting.");
  sgtllc::python::explainSetterTypeErrors(m);  // last: it rewraps the setters of every class bound above
}
