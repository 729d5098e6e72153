/// @file parallel.h
/// @brief The project's one parallel-for (std::thread behind a plain function).
#pragma once

#include <functional>

namespace sgtllc {

/// Calls f(0) … f(n−1) on up to @p threads threads (1 = in order on the caller's thread). Each index runs exactly
/// once; callers write results to per-index slots so the outcome never depends on scheduling. If f throws, the
/// exception reaches the caller: on one thread the later indices do not run; on several, every index runs and the
/// exception of the lowest index that threw is rethrown once all are done.
void parallelFor(int n, int threads, const std::function<void(int)>& f);

}  // namespace sgtllc
