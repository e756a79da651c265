// Jobs on every core (compiler/common/Parallel.h): each index runs once, and a failure is
// rethrown only once every job has stopped, the lowest index's first.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "compiler/common/Parallel.h"

namespace mxc {
namespace {

TEST(Parallel, EachIndexRunsOnce) {
  for (size_t count : {size_t{0}, size_t{1}, size_t{3}, size_t{1000}}) {
    std::vector<std::atomic<int>> runs(count);
    runOnEveryCore(count, [&](size_t i) { ++runs[i]; });
    for (size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 1) << i << " of " << count;
  }
  EXPECT_GE(coreCount(), 1u);
}

TEST(Parallel, TheLowestFailureIsRethrownAfterEveryJobStopped) {
  std::atomic<int> finished{0};
  try {
    runOnEveryCore(64, [&](size_t i) {
      if (i == 40 || i == 17) throw std::runtime_error("job " + std::to_string(i));
      ++finished;
    });
    FAIL() << "no failure rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "job 17");
  }
  EXPECT_EQ(finished.load(), 62);
}

// The pool serves one call at a time; a call nested in a job, or made from another thread while
// the pool is busy, runs on threads of its own. Every index of every call still runs once.
TEST(Parallel, NestedAndConcurrentCallsEachRunEveryIndexOnce) {
  constexpr size_t kOuter = 8, kInner = 50;
  std::vector<std::atomic<int>> runs(kOuter * kInner);
  runOnEveryCore(kOuter, [&](size_t o) {
    runOnEveryCore(kInner, [&](size_t i) { ++runs[o * kInner + i]; });
  });
  for (size_t k = 0; k < runs.size(); ++k) EXPECT_EQ(runs[k].load(), 1) << k;

  std::vector<std::atomic<int>> a(500), b(500);
  std::thread other([&] {
    for (int round = 0; round < 20; ++round) runOnEveryCore(a.size(), [&](size_t i) { ++a[i]; });
  });
  for (int round = 0; round < 20; ++round) runOnEveryCore(b.size(), [&](size_t i) { ++b[i]; });
  other.join();
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].load(), 20) << k;
    EXPECT_EQ(b[k].load(), 20) << k;
  }
}

// The pool's threads are made once: many calls in a row reuse them. Thread ids can repeat
// across threads (glibc reuses stacks), so each thread takes a serial number when it first runs
// a job: a call that made threads of its own would show a new serial each round.
std::atomic<int> threadsSeen{0};
int threadSerial() {
  thread_local const int serial = threadsSeen++;
  return serial;
}

TEST(Parallel, ThePoolsThreadsAreReused) {
  startWorkers();
  std::mutex mutex;
  std::set<int> serials;
  for (int round = 0; round < 20; ++round) {
    runOnEveryCore(8, [&](size_t) {
      // Long enough that every thread of the call takes a job (the caller alone would finish
      // instant jobs before a helper woke).
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      const int serial = threadSerial();
      std::lock_guard<std::mutex> lock(mutex);
      serials.insert(serial);
    });
  }
  EXPECT_LE(serials.size(), coreCount());
}

// `mxc compile -j N`: every job once, on at most N threads at a time, whatever the cores;
// one thread is the caller alone.
TEST(Parallel, RunOnThreadsKeepsToItsCount) {
  for (size_t threads : {size_t(1), size_t(3), coreCount() + 2}) {
    std::vector<std::atomic<int>> runs(24);
    std::atomic<int> running{0}, most{0};
    std::mutex mutex;
    std::set<std::thread::id> ids;
    runOnThreads(runs.size(), threads, [&](size_t i) {
      const int now = ++running;
      for (int seen = most.load(); now > seen && !most.compare_exchange_weak(seen, now);) {
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      ++runs[i];
      {
        std::lock_guard<std::mutex> lock(mutex);
        ids.insert(std::this_thread::get_id());
      }
      --running;
    });
    for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "job " << i << " of " << threads;
    EXPECT_LE(size_t(most.load()), threads);
    EXPECT_LE(ids.size(), threads);
    if (threads == 1) {
      EXPECT_EQ(*ids.begin(), std::this_thread::get_id()) << "the caller's thread alone";
    }
  }
  // A failure is rethrown once every job has stopped, as by runOnEveryCore.
  std::atomic<int> done{0};
  EXPECT_THROW(runOnThreads(8, 3, [&](size_t i) {
                 ++done;
                 if (i == 5) throw std::runtime_error("job 5");
               }),
               std::runtime_error);
  EXPECT_EQ(done.load(), 8);
}

}  // namespace
}  // namespace mxc
