#pragma once
/// \file
/// Writing output files so that nothing is destroyed and nothing is left half-written.
///
/// An output path is resolved first (`resolveOutput`): a symbolic link is followed to the file it
/// names, `-` is standard output, and a path that exists and is not a regular file (a device such
/// as `/dev/null`, a FIFO, a socket) is written through directly: it is never replaced by a
/// regular file. A regular file (or a new one) is written to a temporary file in the same folder,
/// checked at every write and at close, given the mode (and, for root, the owner) of
/// the file it replaces, and renamed over it only once complete. A failure keeps the old file.
/// Temporaries are registered (`TemporaryFiles`) so a termination signal can remove them.

#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace mxc {

/// Where writing an output path leads.
struct OutputTarget {
  enum class Kind {
    Standard,  ///< "-": standard output
    File,      ///< a regular file, or one that does not exist yet: replaced atomically
    Special,   ///< an existing device, FIFO or socket: written through, never replaced
  };
  Kind kind = Kind::File;
  std::filesystem::path requested;  ///< as the user wrote it (for messages)
  std::filesystem::path path;       ///< the file written: symbolic links followed
};

/// Resolves `requested`, or says why it cannot be written (a directory, a missing folder, a loop
/// of symbolic links).
std::variant<OutputTarget, std::string> resolveOutput(const std::filesystem::path& requested);

/// Whether a file can be created beside `target` (a File target): a temporary is made there and
/// removed. Its folder's permission bits do not say (root writes anywhere they forbid; a
/// read-only mount or /sys refuses anyone), so a command checks this before its work rather
/// than finding it when it writes, after minutes of rendering.
std::optional<std::string> folderProblem(const OutputTarget& target);

/// True when the two paths name one existing file (same device and inode: hard links, symbolic
/// links and different spellings included).
bool sameExistingFile(const std::filesystem::path& a, const std::filesystem::path& b);

/// A complete new content for a regular-file target, in a temporary file beside it until
/// `commit` renames it over the target. Destroying an uncommitted one removes the temporary.
class StagedFile {
 public:
  /// Creates the temporary beside `target` (a Kind::File target) and writes `bytes` to it,
  /// checking every write and the close. Errors name the target, never the
  /// temporary.
  static std::variant<StagedFile, std::string> write(const OutputTarget& target, std::string_view bytes);

  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;
  StagedFile(const StagedFile&) = delete;
  ~StagedFile();

  /// Renames the temporary over the target. Call with `TemporaryFiles::lock()` held.
  std::optional<std::string> commit();
  const OutputTarget& target() const { return target_; }

 private:
  StagedFile(OutputTarget target, std::string temporary) : target_(std::move(target)), temporary_(std::move(temporary)) {}
  OutputTarget target_;
  std::string temporary_;  ///< empty once committed or moved from
};

/// Writes `bytes` through to a Kind::Standard or Kind::Special target (no temporary: the target
/// is not a file that could be replaced). Checks every write; a full device is an error.
std::optional<std::string> writeThrough(const OutputTarget& target, std::string_view bytes);

/// One output on its own: resolved, then staged and committed, or written through.
std::optional<std::string> writeOutputFile(const std::filesystem::path& path, std::string_view bytes);

/// The temporary files that exist right now, for a termination signal to remove. Creating and
/// registering a temporary, and committing a set of outputs, happen under `lock()`, so a signal
/// handled on another thread sees either none of a set committed or all of it.
class TemporaryFiles {
 public:
  static std::unique_lock<std::recursive_mutex> lock();
  /// Removes every registered temporary and keeps the lock held for good: for the thread that
  /// handles a termination signal, just before the process ends.
  static void removeAllAndHold();

 private:
  friend class StagedFile;
  friend std::optional<std::string> folderProblem(const OutputTarget& target);
  static void add(const std::string& path);
  static void remove(const std::string& path);
};

}  // namespace mxc
