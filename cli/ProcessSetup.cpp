#include "cli/ProcessSetup.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "compiler/common/OutputFile.h"

namespace mxc::cli {

namespace {

sigset_t terminationSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  sigaddset(&set, SIGHUP);
  return set;
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
