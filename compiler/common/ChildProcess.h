#pragma once
/// \file
/// Running another program (naga, for the WGSL target) and reading what it wrote, in a private
/// temporary folder that is removed afterwards.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mxc {

/// A folder of its own under the system's temporary folder, removed with everything in it when
/// the object is destroyed.
class TemporaryFolder {
 public:
  /// Creates it; empty path() (and `error` set) when it cannot be created.
  explicit TemporaryFolder(std::string& error);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

struct ProcessResult {
  int exitCode = -1;   ///< the status it exited with; -1 when a signal ended it
  std::string output;  ///< its standard output and standard error, interleaved
};

/// Runs `argv` (argv[0] looked up on PATH unless it has a slash) with standard input empty and
/// its output collected in `folder`. nullopt (and `error`) when it cannot be started.
std::optional<ProcessResult> runProcess(const std::vector<std::string>& argv, const std::filesystem::path& folder,
                                        std::string& error);

/// The program `name` on PATH (or `name` itself when it has a slash and exists); empty when none.
std::filesystem::path findProgram(const std::string& name);

}  // namespace mxc
