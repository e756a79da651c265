#pragma once
// Running the mxc binary from tests: arguments in, exit code and both streams out.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "support/TestSupport.h"

namespace mxc::test {

namespace fs = std::filesystem;

struct CommandRun {
  int exitCode = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

/// Runs mxc with arguments (shell-quoted by the caller), capturing both streams. `shell` is
/// run first in the same shell (`ulimit -f 8;`), and `redirect` replaces the capture of stdout
/// (`>/dev/full`, `>&-`).
inline CommandRun mxc(const std::string& arguments, const std::string& shell = {}, const std::string& redirect = {}) {
  const fs::path errFile = fs::temp_directory_path() / ("mxc_cli_err_" + std::to_string(::getpid()));
  std::string command = shell + " " + std::string(MXC_BINARY) + " " + arguments + " 2>" + errFile.string() + " " + redirect;
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

/// A fresh folder under the temporary directory, removed with everything in it at the end.
class TempFolder {
 public:
  explicit TempFolder(const std::string& name) {
    path_ = fs::temp_directory_path() / ("mxc_test_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }
  /// Names of the entries of the folder (hidden ones included), sorted.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

/// mxc started as a child process (no shell), its output streams sent to /dev/null; for tests
/// that signal it or run several at once. Returns the pid, or -1.
inline pid_t spawnMxc(const std::vector<std::string>& arguments) {
  std::vector<std::string> all{MXC_BINARY};
  all.insert(all.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  if (posix_spawn(&pid, MXC_BINARY, &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

inline void writeText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// A document whose material's base colour is the image `file` (its file input on line 4).
inline std::string imageDocument(const std::string& file) {
  return mtlx("  <image name=\"tex\" type=\"color3\">\n    <input name=\"file\" type=\"filename\" value=\"" + file +
              "\" />\n  </image>\n" +
              "  <open_pbr_surface name=\"s\" type=\"surfaceshader\"><input name=\"base_color\" type=\"color3\" "
              "nodename=\"tex\" /></open_pbr_surface>\n"
              "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" "
              "nodename=\"s\" /></surfacematerial>\n");
}

/// A document with two materials, A and B, of one OpenPBR shading node (so one shader code).
inline const char* const kTwoMaterialsOfOneShader =
    "<materialx version=\"1.39\">\n"
    "  <open_pbr_surface name=\"o\" type=\"surfaceshader\"/>\n"
    "  <surfacematerial name=\"A\" type=\"material\"><input name=\"surfaceshader\" "
    "type=\"surfaceshader\" nodename=\"o\"/></surfacematerial>\n"
    "  <surfacematerial name=\"B\" type=\"material\"><input name=\"surfaceshader\" "
    "type=\"surfaceshader\" nodename=\"o\"/></surfacematerial>\n"
    "</materialx>\n";

inline std::string corpus(const std::string& rel) { return (sharedDir() / "corpus" / rel).string(); }

inline fs::path writeTemp(const std::string& name, const std::string& text) {
  fs::path path = fs::temp_directory_path() / ("mxc_cli_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path) << text;
  return path;
}

}  // namespace mxc::test
