// Wall time since a point, in milliseconds: the stage times the pipeline reports (steady clock).
#pragma once

#include <chrono>

namespace sgtllc::pipeline {

inline double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sgtllc::pipeline
