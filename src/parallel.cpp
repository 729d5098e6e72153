#include "sgtllc/parallel.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace sgtllc {
namespace {

/// True on a thread that is running items of a parallelFor: a nested call runs in order there, as OpenMP did
/// with nesting off, so a team never grows past the outer call's thread count.
thread_local bool in_team = false;

/// Hands out items one at a time, so uneven items balance.
void runItems(std::atomic<int>& next, int n, const std::function<void(int)>& f) {
  const bool outer = in_team;
  in_team = true;
  for (int i; (i = next.fetch_add(1, std::memory_order_relaxed)) < n;) f(i);
  in_team = outer;
}

/// How long a worker waits for the next call, and a caller for its workers, before blocking. The online detector's
/// calls come tens of microseconds apart within a frame, and waking a blocked thread on another core costs ~50 µs
/// on a VM. Spinning yields the core, so another process that wants it gets it.
constexpr std::chrono::microseconds kSpin{100};

/// Polls @p ready for up to kSpin; true once it holds.
template <typename Ready>
bool spinUntil(Ready&& ready) {
  const auto end = std::chrono::steady_clock::now() + kSpin;
  for (int k = 1; !ready(); ++k) {
    if (k % 16 == 0 && std::chrono::steady_clock::now() > end) return false;
    std::this_thread::yield();
  }
  return true;
}

/// Workers kept from one call to the next. Starting and joining threads per call cost ~0.1 ms on the project's
/// 2-core VM, and the online detector makes three calls per frame (BENCHMARKS.md "Time per frame"). An idle worker
/// blocks on a condition variable: it never spins (libgomp's spinning workers took a third of `sgtllc eval`'s CPU).
/// One call uses the team at a time; a concurrent call from another thread, or a call in a forked child (which has
/// no workers), starts its own threads instead.
class Team {
 public:
  static Team& instance() {
    static Team* team = new Team;  // never destroyed: blocked workers simply end with the process
    return *team;
  }

  /// Runs f(0 … n−1) on this thread and up to @p helpers workers; false if the team is busy or not this process's.
  bool run(int n, int helpers, const std::function<void(int)>& f) {
    std::unique_lock<std::mutex> call(call_mutex_, std::try_to_lock);
    if (!call.owns_lock() || getpid() != pid_) return false;
    std::atomic<int> next{0};
    {
      std::lock_guard<std::mutex> lock(mutex_);
      try {
        while (static_cast<int>(workers_.size()) < helpers) {
          const int id = static_cast<int>(workers_.size());
          workers_.emplace_back([this, id] { work(id); });
        }
      } catch (const std::system_error&) {
        // No thread to be had (a process limit): the workers there are and this thread do every item.
      }
      job_ = &f;
      next_ = &next;
      n_ = n;
      wanted_ = std::min(helpers, static_cast<int>(workers_.size()));
      pending_.store(wanted_);
      generation_.fetch_add(1);
    }
    wake_.notify_all();
    runItems(next, n, f);
    if (!spinUntil([this] { return pending_.load() == 0; })) {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [this] { return pending_.load() == 0; });
    }
    return true;
  }

 private:
  Team() : pid_(getpid()) {}

  void work(int id) {
    uint64_t seen = 0;
    for (;;) {
      const std::function<void(int)>* job;
      std::atomic<int>* next;
      int n;
      const auto called = [&] { return generation_.load() != seen; };
      if (!spinUntil(called)) {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, called);
      }
      {
        std::lock_guard<std::mutex> lock(mutex_);  // the call's fields were written under it
        seen = generation_.load();
        if (id >= wanted_) continue;  // not needed for this call (fewer items than workers)
        job = job_;
        next = next_;
        n = n_;
      }
      runItems(*next, n, *job);
      if (pending_.fetch_sub(1) == 1) {
        std::lock_guard<std::mutex> lock(mutex_);  // so a caller between its check and its wait is not missed
        done_.notify_one();
      }
    }
  }

  std::mutex call_mutex_;  // held for a whole call
  std::mutex mutex_;       // guards the fields below (the atomics are changed under it too, and read without it)
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void(int)>* job_ = nullptr;
  std::atomic<int>* next_ = nullptr;
  int n_ = 0;
  int wanted_ = 0;    // workers 0 … wanted_−1 take part in the current call
  std::atomic<int> pending_{0};         // of those, the ones not finished yet
  std::atomic<uint64_t> generation_{0};  // calls so far; changed under mutex_
  const pid_t pid_;
};

/// A team started for one call and joined at its end.
void runOwnThreads(int n, int team, const std::function<void(int)>& f) {
  std::atomic<int> next{0};
  std::vector<std::thread> workers;
  workers.reserve(static_cast<size_t>(team - 1));
  try {
    for (int t = 1; t < team; ++t) workers.emplace_back([&] { runItems(next, n, f); });
  } catch (const std::system_error&) {
    // No thread to be had: the workers started so far and this thread do every item.
  }
  runItems(next, n, f);
  for (std::thread& w : workers) w.join();
}

}  // namespace

void parallelFor(int n, int threads, const std::function<void(int)>& f) {
  if (threads <= 1 || n <= 1 || in_team) {
    for (int i = 0; i < n; ++i) f(i);
    return;
  }
  // Never more threads than items (15 candidates need no larger team).
  const int team = std::min(threads, n);
  if (!Team::instance().run(n, team - 1, f)) runOwnThreads(n, team, f);
}

}  // namespace sgtllc
