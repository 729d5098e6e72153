#include "sgtllc/parallel.h"

#include <algorithm>
#include <atomic>
#include <system_error>
#include <thread>
#include <vector>

namespace sgtllc {
namespace {

/// True on a thread that is running items of a parallelFor: a nested call runs in order there, as OpenMP did
/// with nesting off, so a team never grows past the outer call's thread count.
thread_local bool in_team = false;

}  // namespace

void parallelFor(int n, int threads, const std::function<void(int)>& f) {
  if (threads <= 1 || n <= 1 || in_team) {
    for (int i = 0; i < n; ++i) f(i);
    return;
  }
  // Never start more threads than there are items (15 candidates need no larger team). The workers are started
  // per call and end with it: an idle worker never spins. OpenMP's did (libgomp's default wait policy), which took
  // a third of the CPU of `sgtllc eval` and slowed the frame whenever another process wanted the core
  // (BENCHMARKS.md "Time per frame"). Items are handed out one at a time, so uneven items balance.
  const int team = std::min(threads, n);
  std::atomic<int> next{0};
  auto work = [&]() {
    in_team = true;
    for (int i; (i = next.fetch_add(1, std::memory_order_relaxed)) < n;) f(i);
    in_team = false;
  };
  std::vector<std::thread> workers;
  workers.reserve(static_cast<size_t>(team - 1));
  try {
    for (int t = 1; t < team; ++t) workers.emplace_back(work);
  } catch (const std::system_error&) {
    // No thread to be had (a process limit): the workers started so far and this thread do every item.
  }
  work();
  for (std::thread& w : workers) w.join();
}

}  // namespace sgtllc
