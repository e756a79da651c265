#include "cli/AtomicFile.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

namespace mxc::cli {

std::optional<std::string> writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
  namespace fs = std::filesystem;
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return fmt::format("cannot write '{}': folder '{}' does not exist", path.string(), folder.string());
  // Same folder as the target so that rename() is atomic (one file system).
  const fs::path temporary = folder / fmt::format(".{}.tmp-{}", path.filename().string(), ::getpid());
  std::FILE* f = std::fopen(temporary.c_str(), "wb");
  if (!f) return fmt::format("cannot write '{}': {}", temporary.string(), std::strerror(errno));
  const bool written = std::fwrite(contents.data(), 1, contents.size(), f) == contents.size();
  const bool flushed = std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  const bool closed = std::fclose(f) == 0;
  if (!written || !flushed || !closed) {
    std::string reason = std::strerror(errno);
    fs::remove(temporary, ec);
    return fmt::format("cannot write '{}': {}", path.string(), reason);
  }
  fs::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    return fmt::format("cannot write '{}': {}", path.string(), ec.message());
  }
  return std::nullopt;
}

bool writeReport(const std::string& path, std::string_view contents) {
  if (path.empty() || path == "-") {
    std::fwrite(contents.data(), 1, contents.size(), stdout);
    return true;
  }
  if (auto error = writeFileAtomically(path, contents)) {
    std::fprintf(stderr, "error: %s\n", error->c_str());
    return false;
  }
  return true;
}

}  // namespace mxc::cli
