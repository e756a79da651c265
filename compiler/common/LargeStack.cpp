#include "compiler/common/LargeStack.h"

#include <pthread.h>

#include <cstdint>
#include <exception>

namespace mxc {

namespace {

struct Job {
  const std::function<void()>* work;
  std::exception_ptr error;
};

void* runJob(void* argument) {
  auto* job = static_cast<Job*>(argument);
  try {
    (*job->work)();
  } catch (...) {
    job->error = std::current_exception();  // rethrown on the calling thread
  }
  return nullptr;
}

}  // namespace

void runWithLargeStack(const std::function<void()>& work, size_t bytes) {
  Job job{&work, nullptr};
  pthread_attr_t attributes;
  pthread_t thread;
  bool started = false;
  if (pthread_attr_init(&attributes) == 0) {
    started = pthread_attr_setstacksize(&attributes, bytes) == 0 &&
              pthread_create(&thread, &attributes, runJob, &job) == 0;
    pthread_attr_destroy(&attributes);
  }
  if (!started) {
    work();
    return;
  }
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
}

size_t stackRemaining() {
  // The lowest address of this thread's stack, read once per thread (stacks grow down on
  // every platform mxc builds for).
  thread_local uintptr_t lowest = [] {
    uintptr_t low = 0;
    pthread_attr_t attributes;
    if (pthread_getattr_np(pthread_self(), &attributes) == 0) {
      void* address = nullptr;
      size_t size = 0;
      if (pthread_attr_getstack(&attributes, &address, &size) == 0) low = reinterpret_cast<uintptr_t>(address);
      pthread_attr_destroy(&attributes);
    }
    return low;
  }();
  const auto here = reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
  if (lowest == 0 || here <= lowest) return SIZE_MAX;
  return here - lowest;
}

}  // namespace mxc
