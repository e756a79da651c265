#include "compiler/common/OutputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace mxc {

namespace fs = std::filesystem;

namespace {

std::recursive_mutex& registryMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}
std::vector<std::string>& registry() {
  static std::vector<std::string> paths;
  return paths;
}

/// The process's file-creation mask, read without changing it (umask(2) can only be read by
/// setting it, which would race with threads creating files).
mode_t currentUmask() {
  static const mode_t mask = [] {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
      if (line.rfind("Umask:", 0) == 0) return static_cast<mode_t>(std::strtoul(line.c_str() + 6, nullptr, 8));
    }
    return static_cast<mode_t>(022);  // the usual default where /proc does not say
  }();
  return mask;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

/// Writes all of `bytes` to `fd`, retrying short writes and interruptions; errno on failure.
int writeAll(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    if (n == 0) return EIO;  // no progress and no error: do not spin
    done += static_cast<size_t>(n);
  }
  return 0;
}

}  // namespace

std::variant<OutputTarget, std::string> resolveOutput(const fs::path& requested) {
  OutputTarget target;
  target.requested = requested;
  if (requested == "-") {
    target.kind = OutputTarget::Kind::Standard;
    target.path = requested;
    return target;
  }
  if (requested.empty()) return std::string("cannot write to an empty path");
  // Follow symbolic links one at a time (the last may dangle: its target is created), so the
  // file replaced is the one the link names and the link itself stays.
  fs::path path = requested;
  for (int hops = 0;; ++hops) {
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
      if (errno != ENOENT) return fmt::format("cannot write {}: {}", quoted(requested), std::strerror(errno));
      break;  // a new file
    }
    if (S_ISLNK(st.st_mode)) {
      if (hops >= 40) return fmt::format("cannot write {}: a loop of symbolic links", quoted(requested));
      std::error_code ec;
      fs::path next = fs::read_symlink(path, ec);
      if (ec) return fmt::format("cannot write {}: {}", quoted(requested), ec.message());
      path = next.is_absolute() ? next : path.parent_path() / next;
      continue;
    }
    if (S_ISDIR(st.st_mode)) return fmt::format("cannot write {}: it is a directory", quoted(requested));
    if (!S_ISREG(st.st_mode)) {
      target.kind = OutputTarget::Kind::Special;
      target.path = path;
      return target;
    }
    break;
  }
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  struct stat st {};
  if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    return fmt::format("cannot write {}: the folder '{}' does not exist", quoted(requested), folder.string());
  }
  target.kind = OutputTarget::Kind::File;
  target.path = path;
  return target;
}

std::optional<std::string> folderProblem(const OutputTarget& target) {
  const fs::path folder = target.path.has_parent_path() ? target.path.parent_path() : fs::path(".");
  std::string probe = (folder / ".mxc-XXXXXX").string();
  auto held = TemporaryFiles::lock();  // registered while it exists, so a signal removes it too
  const int fd = ::mkostemp(probe.data(), O_CLOEXEC);
  if (fd < 0) return fmt::format("cannot write {}: {}", quoted(target.requested), std::strerror(errno));
  TemporaryFiles::add(probe);
  ::close(fd);
  ::unlink(probe.c_str());
  TemporaryFiles::remove(probe);
  return std::nullopt;
}

bool sameExistingFile(const fs::path& a, const fs::path& b) {
  struct stat sa {}, sb {};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::variant<StagedFile, std::string> StagedFile::write(const OutputTarget& target, std::string_view bytes) {
  const fs::path folder = target.path.has_parent_path() ? target.path.parent_path() : fs::path(".");
  // A short fixed name, not derived from the target's: a target name of 255 bytes is legal, and
  // a suffix on it would not be. mkostemp makes the name unique, so concurrent writers of one
  // path never share a temporary.
  std::string temporary = (folder / ".mxc-XXXXXX").string();
  int fd = -1;
  {
    auto held = TemporaryFiles::lock();  // created and registered as one step (see TemporaryFiles)
    fd = ::mkostemp(temporary.data(), O_CLOEXEC);
    if (fd < 0) return fmt::format("cannot write {}: {}", quoted(target.requested), std::strerror(errno));
    TemporaryFiles::add(temporary);
  }
  StagedFile staged(target, temporary);
  // The new file keeps the mode of the one it replaces (and its owner, where the process may
  // set it); a new file gets the mode open(2) would give it. mkostemp created it 0600.
  struct stat old {};
  if (::stat(target.path.c_str(), &old) == 0) {
    if (::geteuid() == 0) (void)!::fchown(fd, old.st_uid, old.st_gid);  // best effort: the mode matters more
    ::fchmod(fd, old.st_mode & 07777);
  } else {
    ::fchmod(fd, 0666 & ~currentUmask());
  }
  // No fsync before the rename, as compilers and build tools do (gcc, clang, ninja): the rename
  // is what makes the output whole for every reader; a sync only adds durability across a power
  // loss, and it cost a batch compile of the corpus a sixth of its time (225 files, each waiting
  // for the disk). A full disk is still reported: by write() (the file system reserves the blocks
  // then) or, on network file systems, by close().
  int error = writeAll(fd, bytes);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) return fmt::format("cannot write {}: {}", quoted(target.requested), std::strerror(error));
  return staged;
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : target_(std::move(other.target_)), temporary_(std::exchange(other.temporary_, std::string())) {}

StagedFile::~StagedFile() {
  if (temporary_.empty()) return;
  ::unlink(temporary_.c_str());
  TemporaryFiles::remove(temporary_);
}

std::optional<std::string> StagedFile::commit() {
  if (::rename(temporary_.c_str(), target_.path.c_str()) != 0) {
    return fmt::format("cannot write {}: {}", quoted(target_.requested), std::strerror(errno));
  }
  TemporaryFiles::remove(temporary_);
  temporary_.clear();
  return std::nullopt;
}

std::optional<std::string> writeThrough(const OutputTarget& target, std::string_view bytes) {
  if (target.kind == OutputTarget::Kind::Standard) {
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), stdout) == bytes.size() && std::fflush(stdout) == 0;
    if (!ok) return fmt::format("cannot write to standard output: {}", std::strerror(errno));
    return std::nullopt;
  }
  // No O_TRUNC and no temporary: a device or FIFO is written as it is. A FIFO's open waits for
  // a reader, as a shell redirection would.
  const int fd = ::open(target.path.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return fmt::format("cannot write {}: {}", quoted(target.requested), std::strerror(errno));
  int error = writeAll(fd, bytes);
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) return fmt::format("cannot write {}: {}", quoted(target.requested), std::strerror(error));
  return std::nullopt;
}

std::optional<std::string> writeOutputFile(const fs::path& path, std::string_view bytes) {
  auto resolved = resolveOutput(path);
  if (auto* error = std::get_if<std::string>(&resolved)) return *error;
  const OutputTarget& target = std::get<OutputTarget>(resolved);
  if (target.kind != OutputTarget::Kind::File) return writeThrough(target, bytes);
  auto staged = StagedFile::write(target, bytes);
  if (auto* error = std::get_if<std::string>(&staged)) return *error;
  auto held = TemporaryFiles::lock();
  return std::get<StagedFile>(staged).commit();
}

std::unique_lock<std::recursive_mutex> TemporaryFiles::lock() { return std::unique_lock(registryMutex()); }

void TemporaryFiles::add(const std::string& path) {
  auto held = lock();
  registry().push_back(path);
}

void TemporaryFiles::remove(const std::string& path) {
  auto held = lock();
  auto& paths = registry();
  paths.erase(std::remove(paths.begin(), paths.end(), path), paths.end());
}

void TemporaryFiles::removeAllAndHold() {
  registryMutex().lock();  // never unlocked: the process is about to end
  for (const std::string& path : registry()) ::unlink(path.c_str());
  registry().clear();
}

}  // namespace mxc
