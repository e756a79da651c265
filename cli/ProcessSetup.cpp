#include "cli/ProcessSetup.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#include "compiler/common/OutputFile.h"
#include "compiler/common/TerminationSignals.h"

namespace mxc::cli {

namespace {

/// Every signal whose default action ends the process and that arrives from outside it (kill,
/// a terminal, a timer): each is taken by one thread that removes the temporaries first.
/// SIGPIPE as well: sent by another process it is taken the same way, and raised by a write to
/// a closed pipe it stays pending on the writing thread (blocked, so not delivered), the write
/// fails with EPIPE and the command reports it (exit 3) and removes its temporaries as for any
/// failed write. The signals of faults (SIGSEGV, SIGBUS, SIGFPE, SIGILL) are not here: they
/// cannot be blocked usefully.
sigset_t terminationSignals() {
  sigset_t set;
  sigemptyset(&set);
  for (int signal : kTerminationSignals) sigaddset(&set, signal);
  return set;
}

/// Address space held back for when memory runs out. Destructors allocate (a large
/// nlohmann::json frees its elements through a vector of them), and an allocation that fails in
/// a destructor ends the process (std::terminate, exit 134) instead of exit 4, so:
/// - `retry` is given back at the first failure outside an unwinding, and the allocation tried
///   again: a destructor that runs out on the normal path finishes (the work goes on in it);
/// - `unwind` is given back when a failure is to throw std::bad_alloc (the next failure outside
///   an unwinding), so that the destructors of the unwinding find room;
/// - a failure during an unwinding gives back what is left and tries again.
/// Mapped PROT_NONE and never touched: they cost address space (what `ulimit -v` counts) and no
/// memory. mmap and munmap rather than the allocator, which would keep a freed block for itself
/// (mimalloc caches segments) where allocations of other sizes cannot reach it.
struct Reserve {
  void* address = nullptr;
  size_t bytes = 0;
  void map(size_t size) {
    void* mapped = ::mmap(nullptr, size, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (mapped != MAP_FAILED) address = mapped, bytes = size;
  }
  /// Gives the reserve back; false when it was given back already. Atomic: of two threads that
  /// run out together, one gives it back.
  bool release() {
    void* mine = __atomic_exchange_n(&address, nullptr, __ATOMIC_ACQ_REL);
    if (!mine) return false;
    ::munmap(mine, bytes);
    return true;
  }
};
Reserve retryReserve, unwindReserve;

void onOutOfMemory() {
  if (std::uncaught_exceptions() > 0) {
    if (unwindReserve.release() || retryReserve.release()) return;
  } else {
    if (retryReserve.release()) return;
    unwindReserve.release();
  }
  throw std::bad_alloc();
}

void* waitForTermination(void*) {
  const sigset_t set = terminationSignals();
  int signal = 0;
  while (sigwait(&set, &signal) != 0) {
  }
  // Waits for a commit under way, then removes what is not committed; the lock stays held so no
  // new temporary appears before the process ends.
  TemporaryFiles::removeAllAndHold();
  // End by the signal itself, so the parent sees "killed by SIGINT" as for any program.
  ::signal(signal, SIG_DFL);
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, signal);
  pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
  ::raise(signal);
  _exit(128 + signal);  // not reached: the default action of these signals ends the process
}

/// Reopens a closed standard descriptor on /dev/null.
void reopenIfClosed(int fd, int flags) {
  if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) return;
  // open() returns the lowest free descriptor: `fd`, since the lower ones are open by now.
  const int opened = ::open("/dev/null", flags | O_CLOEXEC);
  if (opened >= 0 && opened != fd) {
    ::dup2(opened, fd);
    ::close(opened);
  }
}

}  // namespace

void setUpProcess() {
  retryReserve.map(32u << 20);
  unwindReserve.map(64u << 20);
  std::set_new_handler(onOutOfMemory);
  reopenIfClosed(STDIN_FILENO, O_RDONLY);
  // Read-only: what mxc writes to a standard output that was closed fails, and is reported.
  reopenIfClosed(STDOUT_FILENO, O_RDONLY);
  reopenIfClosed(STDERR_FILENO, O_WRONLY);
  ::signal(SIGXFSZ, SIG_IGN);
  const sigset_t set = terminationSignals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);  // inherited by every thread created from now on
  pthread_attr_t attributes;
  pthread_t thread;
  if (pthread_attr_init(&attributes) != 0) return;
  pthread_attr_setdetachstate(&attributes, PTHREAD_CREATE_DETACHED);
  pthread_attr_setstacksize(&attributes, 64 * 1024);
  if (pthread_create(&thread, &attributes, waitForTermination, nullptr) != 0) {
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);  // no thread to take them: default behaviour
  }
  pthread_attr_destroy(&attributes);
}

bool flushStandardOutput() {
  errno = 0;
  const bool ok = std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (!ok) {
    std::fprintf(stderr, "error: cannot write to standard output: %s\n",
                 errno != 0 ? std::strerror(errno) : "write error");
  }
  return ok;
}

}  // namespace mxc::cli
