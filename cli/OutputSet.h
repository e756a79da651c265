#pragma once
/// \file
/// The outputs of one command, written together: declared and checked before the work, staged
/// as each is produced, and committed at the end only when every one of them was produced.
///
/// What holds (README, "Outputs"):
/// - an output is never an input of the command, and no two outputs name one file (usage error);
/// - until `commit`, no output path has changed: files are staged in temporaries beside them;
/// - `commit` renames every staged file with termination signals held off, so an interrupt
///   leaves all of the regular files of the set replaced or none;
/// - outputs that are not regular files (standard output, a device, a FIFO) are written first,
///   directly, since there is nothing to replace atomically; the regular files are replaced
///   only when every one of those succeeded;
/// - a failure, or the set destroyed uncommitted, removes every temporary and keeps old files.

#include <filesystem>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "compiler/common/OutputFile.h"

namespace mxc::cli {

class OutputSet {
 public:
  /// Declares an output path, named in messages by `option` ("-o", "--glsl"). Returns why the
  /// path cannot be written (a directory, a missing folder): an output failure, exit code 3.
  std::optional<std::string> declare(const std::filesystem::path& path, const std::string& option);
  /// A usage error (exit code 2) when two declared outputs name the same file (a device such as
  /// /dev/null excepted: nothing of it is replaced).
  std::optional<std::string> checkDistinct() const;
  /// A usage error when a declared output is the existing file `input` (`what` says which input:
  /// "the document", "an included document", "the mesh", ...).
  std::optional<std::string> checkNotInput(const std::filesystem::path& input, const std::string& what) const;

  /// The content of a declared output. A regular file is staged now (so a full disk is known at
  /// once and the bytes need not be kept); others are kept until `commit`.
  std::optional<std::string> stage(const std::filesystem::path& path, std::string bytes);
  /// The declared paths, as they were given, in the order they were declared.
  std::vector<std::filesystem::path> paths() const;
  /// Whether every declared output has been staged.
  bool complete() const;

  /// Commits every staged output (see the file comment). An error names the output that failed.
  std::optional<std::string> commit();

 private:
  struct Entry {
    OutputTarget target;
    std::string option;
    std::optional<StagedFile> staged;  ///< a regular file's temporary
    std::optional<std::string> bytes;  ///< standard output's or a special file's content
  };
  Entry* find(const std::filesystem::path& path);
  std::vector<Entry> entries_;
  /// The first entry of each requested path (stage() looks outputs up by it).
  std::unordered_map<std::string, size_t> byRequested_;
  std::unordered_set<std::string> probedFolders_;  ///< folders a file was created in (folderProblem)
};

/// Prints "error: MESSAGE" to stderr when there is a message; returns whether there was one.
bool printError(const std::optional<std::string>& error);

}  // namespace mxc::cli
