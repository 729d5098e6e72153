// parallelFor (include/sgtllc/parallel.h): every index exactly once at any thread count, no more threads than
// asked for, a nested call run in order on the calling thread, and an exception of an item rethrown on the caller.
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "sgtllc/parallel.h"

namespace {

TEST(ParallelFor, EveryIndexExactlyOnceAtAnyThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    for (int n : {0, 1, 2, 7, 1000}) {
      std::vector<std::atomic<int>> hits(static_cast<size_t>(n));
      sgtllc::parallelFor(n, threads, [&](int i) { hits[static_cast<size_t>(i)].fetch_add(1); });
      for (int i = 0; i < n; ++i) EXPECT_EQ(hits[static_cast<size_t>(i)].load(), 1) << threads << " threads, n " << n;
    }
  }
}

TEST(ParallelFor, AtMostTheThreadsAskedForAndOneRunsInOrderOnTheCaller) {
  std::mutex m;
  std::set<std::thread::id> ids;
  sgtllc::parallelFor(200, 3, [&](int) {
    std::this_thread::yield();
    const std::lock_guard<std::mutex> lock(m);
    ids.insert(std::this_thread::get_id());
  });
  EXPECT_LE(ids.size(), 3u);
  EXPECT_GE(ids.size(), 1u);
  // One thread: in order, on the caller.
  std::vector<int> order;
  const std::thread::id caller = std::this_thread::get_id();
  sgtllc::parallelFor(5, 1, [&](int i) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    order.push_back(i);
  });
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(ParallelFor, NestedCallRunsInOrderOnTheCallingThread) {
  std::vector<std::vector<int>> inner(4);
  std::vector<int> same_thread(4, 1);
  sgtllc::parallelFor(4, 2, [&](int i) {
    const std::thread::id outer = std::this_thread::get_id();
    sgtllc::parallelFor(6, 4, [&](int k) {
      if (std::this_thread::get_id() != outer) same_thread[static_cast<size_t>(i)] = 0;
      inner[static_cast<size_t>(i)].push_back(k);  // only this item's thread writes here
    });
  });
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(same_thread[static_cast<size_t>(i)], 1);
    EXPECT_EQ(inner[static_cast<size_t>(i)], (std::vector<int>{0, 1, 2, 3, 4, 5}));
  }
  // After the outer call, this thread starts a team again: item 0 waits for item 1, which only another thread can
  // run meanwhile (in order, item 1 would start after item 0 gave up waiting).
  std::atomic<bool> second_ran{false};
  bool waited = false;
  sgtllc::parallelFor(2, 2, [&](int i) {
    if (i == 1) {
      second_ran = true;
      return;
    }
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!second_ran && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
    waited = second_ran;
  });
  EXPECT_TRUE(waited);
}

TEST(ParallelFor, KeptWorkersServeManyCallsAndConcurrentCallersEachGetEveryIndex) {
  // The workers kept between calls (src/parallel.cpp): thousands of calls of different sizes and thread counts in a
  // row, then two threads calling at once (one gets the kept workers, the other starts its own), each call's items
  // exactly once.
  for (int call = 0; call < 3000; ++call) {
    const int n = 1 + call % 17, threads = 2 + call % 3;
    std::vector<std::atomic<int>> hits(static_cast<size_t>(n));
    sgtllc::parallelFor(n, threads, [&](int i) { hits[static_cast<size_t>(i)].fetch_add(1); });
    for (int i = 0; i < n; ++i) ASSERT_EQ(hits[static_cast<size_t>(i)].load(), 1) << "call " << call;
  }
  std::atomic<int> bad{0};
  auto caller = [&](int seed) {
    for (int call = 0; call < 500; ++call) {
      const int n = 2 + (call + seed) % 9;
      std::vector<std::atomic<int>> hits(static_cast<size_t>(n));
      sgtllc::parallelFor(n, 2, [&](int i) { hits[static_cast<size_t>(i)].fetch_add(1); });
      for (int i = 0; i < n; ++i) bad += hits[static_cast<size_t>(i)].load() != 1 ? 1 : 0;
    }
  };
  std::thread a(caller, 0), b(caller, 5);
  a.join();
  b.join();
  EXPECT_EQ(bad.load(), 0);
}

TEST(ParallelFor, AnExceptionReachesTheCallerAfterEveryItem) {
  // Items 3 and 7 throw: the caller gets item 3's exception (the lowest index), and with a team every other item has
  // run by then, so nothing still uses the call's state; the team then serves the next call.
  for (int threads : {2, 3}) {
    std::vector<std::atomic<int>> hits(10);
    try {
      sgtllc::parallelFor(10, threads, [&](int i) {
        hits[static_cast<size_t>(i)].fetch_add(1);
        if (i == 3 || i == 7) throw std::runtime_error("item " + std::to_string(i));
      });
      ADD_FAILURE() << "no exception at " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "item 3");
    }
    for (int i = 0; i < 10; ++i) EXPECT_EQ(hits[static_cast<size_t>(i)].load(), 1) << threads << " threads, item " << i;
    std::atomic<int> after{0};
    sgtllc::parallelFor(100, threads, [&](int) { after.fetch_add(1); });
    EXPECT_EQ(after.load(), 100);
  }
  // One thread: in order, so item 3 throws and the items after it do not run.
  std::vector<int> ran;
  EXPECT_THROW(sgtllc::parallelFor(10, 1, [&](int i) {
                 ran.push_back(i);
                 if (i == 3) throw std::runtime_error("item 3");
               }),
               std::runtime_error);
  EXPECT_EQ(ran, (std::vector<int>{0, 1, 2, 3}));
}

}  // namespace
