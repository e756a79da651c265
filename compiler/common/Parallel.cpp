#include "compiler/common/Parallel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace mxc {

size_t coreCount() { return std::max(1u, std::thread::hardware_concurrency()); }

namespace {

/// One call's jobs, shared by the caller and the threads that help it.
struct Batch {
  size_t count = 0;
  const std::function<void(size_t)>* job = nullptr;
  std::atomic<size_t> next{0};
  std::vector<std::exception_ptr> failures;

  void work() {
    for (size_t i = next++; i < count; i = next++) {
      try {
        (*job)(i);
      } catch (...) {
        failures[i] = std::current_exception();
      }
    }
  }
};

/// coreCount() - 1 threads parked on a condition variable, serving one batch at a time.
class Pool {
 public:
  explicit Pool(size_t helpers) {
    // A thread that cannot be made leaves the pool smaller; a pool of none runs every batch on
    // its caller.
    for (size_t t = 0; t < helpers; ++t) {
      try {
        std::thread(&Pool::serve, this).detach();
        ++threads_;
      } catch (const std::system_error&) {
        break;
      }
    }
  }

  /// Runs the batch with the pool's help; false (nothing run) when the pool serves another.
  bool tryRun(Batch& batch) {
    std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    if (!busy.owns_lock()) return false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      batch_ = &batch;
      ++generation_;
      working_ = threads_;
    }
    wake_.notify_all();
    batch.work();
    std::unique_lock<std::mutex> lock(mutex_);
    // The batch lives on the caller's stack: every helper must have left it before it returns.
    done_.wait(lock, [&] { return working_ == 0; });
    batch_ = nullptr;
    return true;
  }

 private:
  void serve() {
    size_t seen = 0;
    for (;;) {
      Batch* batch = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return generation_ != seen; });
        seen = generation_;
        batch = batch_;
      }
      batch->work();
      std::lock_guard<std::mutex> lock(mutex_);
      if (--working_ == 0) done_.notify_one();
    }
  }

  std::mutex busy_;   // held by the caller whose batch the pool serves
  std::mutex mutex_;  // guards the fields below
  std::condition_variable wake_, done_;
  Batch* batch_ = nullptr;
  size_t generation_ = 0;  // batches started: a helper serves each once
  size_t working_ = 0;     // helpers not yet done with the current batch
  size_t threads_ = 0;
};

/// The process's pool, made on first use and never destroyed: its threads are parked for the
/// whole process, and destroying it at exit would pull the mutex from under them.
Pool& pool() {
  static Pool* const instance = new Pool(coreCount() - 1);
  return *instance;
}

}  // namespace

void startWorkers() { pool(); }

void runOnThreads(size_t count, size_t threads, const std::function<void(size_t)>& job) {
  Batch batch;
  batch.count = count;
  batch.job = &job;
  batch.failures.resize(count);
  if (count <= 1 || threads <= 1) {
    batch.work();
  } else if (threads != coreCount() || !pool().tryRun(batch)) {
    // Another count than the pool's, or the pool is busy (a nested call, or another thread's):
    // threads of this call's own.
    std::vector<std::thread> helpers;
    for (size_t t = 1; t < std::min(count, threads); ++t) helpers.emplace_back([&] { batch.work(); });
    batch.work();
    for (std::thread& helper : helpers) helper.join();
  }
  for (const std::exception_ptr& failure : batch.failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

void runOnEveryCore(size_t count, const std::function<void(size_t)>& job) { runOnThreads(count, coreCount(), job); }

}  // namespace mxc
