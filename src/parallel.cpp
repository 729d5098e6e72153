#include "sgtllc/parallel.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
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
/// polls for at most kSpin, yielding the core, then blocks on a condition variable: it never spins between frames
/// (libgomp's spinning workers took a third of `sgtllc eval`'s CPU).
/// A worker takes part in a call only if it joins while the call is open; the caller closes the call once every
/// item is handed out and then waits for the workers that joined, never for one the scheduler has not run yet (on a
/// busy machine that wait was a whole time slice, ~4 ms, per call). One call uses the team at a time; a concurrent
/// call from another thread, or a call in a forked child (which has no workers), starts its own threads instead.
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
      n_ = n;
      next_.store(0);
      wanted_ = std::min(helpers, static_cast<int>(workers_.size()));
      open_ = true;
      generation_.fetch_add(1);
    }
    wake_.notify_all();
    runItems(next_, n, f);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      open_ = false;  // every item is handed out: a worker that has not joined by now stays out of this call
    }
    if (!spinUntil([this] { return joined_.load() == 0; })) {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [this] { return joined_.load() == 0; });
    }
    return true;
  }

 private:
  Team() : pid_(getpid()) {}

  void work(int id) {
    uint64_t seen = 0;
    for (;;) {
      const std::function<void(int)>* job;
      int n;
      const auto called = [&] { return generation_.load() != seen; };
      if (!spinUntil(called)) {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, called);
      }
      {
        std::lock_guard<std::mutex> lock(mutex_);  // the call's fields were written under it
        seen = generation_.load();
        if (!open_ || id >= wanted_) continue;  // too late for this call, or not needed (fewer items than workers)
        joined_.fetch_add(1);
        job = job_;
        n = n_;
      }
      runItems(next_, n, *job);
      if (joined_.fetch_sub(1) == 1) {
        std::lock_guard<std::mutex> lock(mutex_);  // so a caller between its check and its wait is not missed
        done_.notify_one();
      }
    }
  }

  std::mutex call_mutex_;  // held for a whole call
  // Guards the fields below; of the atomics, generation_ and next_'s reset and joined_'s increments change under it,
  // next_'s hand-outs and joined_'s decrements without it, and all are read without it.
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void(int)>* job_ = nullptr;
  int n_ = 0;
  std::atomic<int> next_{0};   // the current call's next item
  int wanted_ = 0;             // workers 0 … wanted_−1 may join the current call
  bool open_ = false;          // workers may still join the current call
  std::atomic<int> joined_{0};  // workers that joined the current call and are not done
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
  // An exception must not leave a team's thread (std::terminate) or unwind the caller while the workers still use
  // this call's state: it is caught per item, and the one of the lowest index is rethrown once every item is done.
  std::mutex failure_mutex;
  int failed_index = n;
  std::exception_ptr failure;
  const std::function<void(int)> guarded = [&](int i) {
    try {
      f(i);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failure_mutex);
      if (i < failed_index) {
        failed_index = i;
        failure = std::current_exception();
      }
    }
  };
  // Never more threads than items (15 candidates need no larger team).
  const int team = std::min(threads, n);
  if (!Team::instance().run(n, team - 1, guarded)) runOwnThreads(n, team, guarded);
  if (failure) std::rethrow_exception(failure);
}

}  // namespace sgtllc
