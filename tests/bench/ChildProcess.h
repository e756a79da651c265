#pragma once
// A program run as a child process by a benchmark, with its wall time and, from the kernel's
// accounting (wait4), its peak resident memory: what a user of the command meets.

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

namespace mxc::bench {

struct ChildRun {
  bool ok = false;       ///< exited with status 0
  double seconds = 0.0;  ///< fork to exit
  double peakMiB = 0.0;  ///< peak resident set
};

/// Runs `program` with `args` (argv[0] is "mxc"), its standard output discarded, and its
/// standard error too unless `keepErrors`. The child's peak counts the pages it had from fork
/// until exec, so call it while the benchmark process is small.
inline ChildRun runChild(const char* program, const std::vector<std::string>& args, bool keepErrors = false) {
  std::vector<char*> argv{const_cast<char*>("mxc")};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid == 0) {
    const int devnull = ::open("/dev/null", O_WRONLY);
    ::dup2(devnull, 1);
    if (!keepErrors) ::dup2(devnull, 2);
    execv(program, argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  ChildRun run;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.peakMiB = double(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
  run.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return run;
}

}  // namespace mxc::bench
