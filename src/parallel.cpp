#include "sgtllc/parallel.h"

#include <algorithm>

namespace sgtllc {

void parallelFor(int n, int threads, const std::function<void(int)>& f) {
  if (threads <= 1 || n <= 1) {
    for (int i = 0; i < n; ++i) f(i);
    return;
  }
  // Never start more threads than there are items (15 candidates need no larger team).
  const int team = std::min(threads, n);
#pragma omp parallel for num_threads(team) schedule(dynamic, 1)
  for (int i = 0; i < n; ++i) f(i);
}

}  // namespace sgtllc
