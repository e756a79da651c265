#pragma once
// Running the mxc binary from tests: arguments in, exit code and both streams out.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>

#include "support/TestSupport.h"

namespace mxc::test {

namespace fs = std::filesystem;

struct CommandRun {
  int exitCode = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

/// Runs mxc with arguments (shell-quoted by the caller), capturing both streams.
inline CommandRun mxc(const std::string& arguments) {
  const fs::path errFile = fs::temp_directory_path() / ("mxc_cli_err_" + std::to_string(::getpid()));
  std::string command = std::string(MXC_BINARY) + " " + arguments + " 2>" + errFile.string();
  CommandRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) run.out.append(buffer.data(), n);
  int status = ::pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(errFile);
  run.err.assign(std::istreambuf_iterator<char>(err), {});
  fs::remove(errFile);
  return run;
}

inline std::string corpus(const std::string& rel) { return (sharedDir() / "corpus" / rel).string(); }

inline fs::path writeTemp(const std::string& name, const std::string& text) {
  fs::path path = fs::temp_directory_path() / ("mxc_cli_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path;
}

}  // namespace mxc::test
