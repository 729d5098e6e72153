/// @file parallel.h
/// @brief The project's one parallel-for (std::thread behind a plain function).
#pragma once

#include <functional>

namespace sgtllc {

/// Calls f(0) … f(n−1) on up to @p threads threads (1 = in order on the caller's thread). Each index runs exactly
/// once; callers write results to per-index slots so the outcome never depends on scheduling. f must not throw.
void parallelFor(int n, int threads, const std::function<void(int)>& f);

}  // namespace sgtllc
