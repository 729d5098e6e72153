#include "sgtllc/parallel.h"

namespace sgtllc {

void parallelFor(int n, int threads, const std::function<void(int)>& f) {
  if (threads <= 1 || n <= 1) {
    for (int i = 0; i < n; ++i) f(i);
    return;
  }
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (int i = 0; i < n; ++i) f(i);
}

}  // namespace sgtllc
