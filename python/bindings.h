// Private to the Python module: one function per concept adds its classes and functions to the module.
#pragma once

#include <pybind11/pybind11.h>

namespace sgtllc::map {
struct Map;
}  // namespace sgtllc::map

namespace sgtllc::python {

namespace py = pybind11;

void bindConfig(py::module_& m);         // config.cpp: Config and its sections, enums, YAML
void bindBackendConfig(py::module_& m);  // config_backend.cpp: BackendConfig and its sections
void bindLabel(py::module_& m);         // label.cpp: the geometric labeller, LabellerConfig (labeller.*)
void bindRegistration(py::module_& m);  // registration.cpp: RegistrationConfig, Refinement
void bindResults(py::module_& m);        // results.cpp: MatchResult, FrameResult, PairResult, stage times
void bindDetector(py::module_& m);       // detector.cpp: LoopDetector, compare_pair, compare_nodes
void bindIo(py::module_& m);             // io.cpp: KITTI, PCD, node files, poses, calib, sequence folders
void bindMetrics(py::module_& m);        // metrics.cpp: PR curve, F1max, EP, pose and trajectory errors
void bindRepeatability(py::module_& m);  // repeatability.cpp: node repeatability, label agreement
void bindBackend(py::module_& m);        // backend.cpp: the pose-graph optimiser
void bindAccumulate(py::module_& m);     // accumulate.cpp: ScanAccumulator (scan accumulation)
void bindMap(py::module_& m);            // map.cpp: Map, load_map, Relocalizer
void bindPipeline(py::module_& m);       // pipeline.cpp: LoopClosingPipeline and what it returns
void bindSessions(py::module_& m);       // sessions.cpp: SessionPipeline, a new session merged into a map

/// A copy of @p m (the C++ Map is move-only; Python objects share theirs).
map::Map copyMap(const map::Map& m);
void bindRelocalization(py::module_& m);  // relocalization.cpp: the relocalization protocol's metrics
void explainSetterTypeErrors(py::module_& m);  // typed_setters.cpp: "Class.field: expected T, got U" TypeErrors

}  // namespace sgtllc::python
