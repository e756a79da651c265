#include "compiler/common/InputFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace mxc {

namespace {

/// What a file of mode `mode` is, when it is not a regular file.
std::optional<std::string> kindProblem(mode_t mode) {
  if (S_ISREG(mode)) return std::nullopt;
  if (S_ISDIR(mode)) return "it is a directory, not a file";
  if (S_ISFIFO(mode)) return "it is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode)) return "it is a character device, not a regular file";
  if (S_ISBLK(mode)) return "it is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

std::string systemReason(int error) {
  if (error == ENOENT) return "it does not exist";
  if (error == ELOOP) return "it is a loop of symbolic links";
  return std::strerror(error);
}

}  // namespace

std::optional<std::string> inputFileProblem(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return systemReason(errno);
  return kindProblem(st.st_mode);
}

std::variant<std::string, std::string> readInputFile(const std::filesystem::path& path, size_t maxBytes) {
  using Result = std::variant<std::string, std::string>;
  auto fail = [](std::string why) { return Result(std::in_place_index<1>, std::move(why)); };
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer. The descriptor is
  // checked before anything is read, so the flag never changes how a regular file reads.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    // A directory opens read-only on Linux; other refusals carry their reason.
    return fail(systemReason(errno));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) return fail(systemReason(errno));
  if (auto problem = kindProblem(st.st_mode)) return fail(*problem);
  const auto size = static_cast<uint64_t>(st.st_size);
  if (size > maxBytes) return fail(fmt::format("it is {} bytes, above the limit of {} bytes", size, maxBytes));
  std::string bytes(static_cast<size_t>(size), '\0');
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return fail(systemReason(errno));
    if (n == 0) break;  // the file shrank while it was read: what is there is what it holds
    done += static_cast<size_t>(n);
  }
  bytes.resize(done);
  return Result(std::in_place_index<0>, std::move(bytes));
}

}  // namespace mxc
