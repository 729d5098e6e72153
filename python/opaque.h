// Private to the Python module: configuration containers bound by reference, so that
// `config.cluster.classes[0].radius = 2.0` and `config.labels.custom_map[10] = 0` change the configuration itself
// rather than a converted copy. Included by every file of the module (the declaration must be seen everywhere).
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include <pybind11/pybind11.h>

#include "sgtllc/config.h"

PYBIND11_MAKE_OPAQUE(std::vector<sgtllc::ClassClusterConfig>)
PYBIND11_MAKE_OPAQUE(std::vector<sgtllc::ExtraClass>)
PYBIND11_MAKE_OPAQUE(std::map<uint32_t, int>)
