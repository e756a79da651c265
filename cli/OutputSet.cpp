#include "cli/OutputSet.h"

#include <sys/stat.h>

#include <cstdio>
#include <map>

#include <fmt/format.h>

namespace mxc::cli {

namespace fs = std::filesystem;

namespace {

/// What names a target, computed once per target: the file it is (device and inode) when it
/// exists, and its path with the symbolic links of its folder resolved. Two targets are the same
/// when both exist as one file, or when those paths are equal. Standard output is one target.
struct TargetIdentity {
  bool standard = false;
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  fs::path resolved;
};

}  // namespace

std::optional<std::string> OutputSet::declare(const fs::path& path, const std::string& option) {
  auto resolved = resolveOutput(path);
  if (auto* error = std::get_if<std::string>(&resolved)) return fmt::format("{}: {}", option, *error);
  // Once per folder: a batch declares a hundred thousand outputs in a few.
  const OutputTarget& target = std::get<OutputTarget>(resolved);
  if (target.kind == OutputTarget::Kind::File && probedFolders_.insert(target.path.parent_path().native()).second) {
    if (auto problem = folderProblem(target)) return fmt::format("{}: {}", option, *problem);
  }
  entries_.push_back({std::move(std::get<OutputTarget>(resolved)), option, std::nullopt, std::nullopt});
  byRequested_.try_emplace(entries_.back().target.requested.native(), entries_.size() - 1);  // the first keeps it
  return std::nullopt;
}

std::optional<std::string> OutputSet::checkDistinct() const {
  // A command's outputs share a folder or a few: each folder is resolved once (a path's
  // resolution stats and reads the links of every component), each target stated once.
  std::map<fs::path, fs::path> folders;
  std::vector<TargetIdentity> identities(entries_.size());
  for (size_t i = 0; i < entries_.size(); ++i) {
    const OutputTarget& t = entries_[i].target;
    TargetIdentity& id = identities[i];
    id.standard = t.kind == OutputTarget::Kind::Standard;
    if (id.standard) continue;
    struct stat st {};
    if (::stat(t.path.c_str(), &st) == 0) {
      id.exists = true;
      id.device = st.st_dev;
      id.inode = st.st_ino;
    }
    std::error_code ec;
    const fs::path absolute = fs::absolute(t.path, ec);
    auto [folder, added] = folders.try_emplace(absolute.parent_path());
    if (added) folder->second = fs::weakly_canonical(folder->first, ec);
    id.resolved = folder->second / absolute.filename();
  }
  // Each target against those before it through two maps (the file it is, and its resolved
  // path), not pairwise: a batch declares a hundred thousand outputs.
  std::map<std::pair<dev_t, ino_t>, size_t> byFile;
  std::map<fs::path, size_t> byPath;
  std::optional<size_t> standard;
  for (size_t i = 0; i < entries_.size(); ++i) {
    const TargetIdentity& id = identities[i];
    std::optional<size_t> earlier;
    if (id.standard) {
      earlier = standard;
      if (!standard) standard = i;
    } else {
      if (id.exists) {
        auto [at, added] = byFile.try_emplace({id.device, id.inode}, i);
        if (!added) earlier = at->second;
      }
      auto [at, added] = byPath.try_emplace(id.resolved, i);
      if (!added && !earlier) earlier = at->second;
    }
    // A device is written through, never replaced: two outputs may name it (/dev/null).
    if (!earlier || entries_[i].target.kind == OutputTarget::Kind::Special) continue;
    const Entry &a = entries_[*earlier], &b = entries_[i];
    return fmt::format("{} '{}' and {} '{}' name the same file: one would overwrite the other", a.option,
                       a.target.requested.string(), b.option, b.target.requested.string());
  }
  return std::nullopt;
}

std::optional<std::string> OutputSet::checkNotInput(const fs::path& input, const std::string& what) const {
  for (const Entry& e : entries_) {
    if (e.target.kind == OutputTarget::Kind::Standard) continue;
    // A device can be read and written at once without harm (/dev/null as a mesh and an output
    // is refused elsewhere, as an input that is not a regular file).
    if (e.target.kind == OutputTarget::Kind::Special) continue;
    if (sameExistingFile(e.target.path, input)) {
      return fmt::format("{} '{}' names {} ('{}'): writing it would destroy that input", e.option,
                         e.target.requested.string(), what, input.string());
    }
  }
  return std::nullopt;
}

OutputSet::Entry* OutputSet::find(const fs::path& path) {
  auto found = byRequested_.find(path.native());
  return found == byRequested_.end() ? nullptr : &entries_[found->second];
}

std::vector<std::filesystem::path> OutputSet::paths() const {
  std::vector<std::filesystem::path> out;
  for (const Entry& e : entries_) out.push_back(e.target.requested);
  return out;
}

bool OutputSet::complete() const {
  for (const Entry& e : entries_) {
    if (!e.staged && !e.bytes) return false;
  }
  return true;
}

std::optional<std::string> OutputSet::stage(const fs::path& path, std::string bytes) {
  Entry* e = find(path);
  if (!e) return fmt::format("internal error: the output '{}' was not declared", path.string());
  if (e->target.kind != OutputTarget::Kind::File) {
    e->bytes = std::move(bytes);
    return std::nullopt;
  }
  auto staged = StagedFile::write(e->target, bytes);
  if (auto* error = std::get_if<std::string>(&staged)) return *error;
  e->staged.emplace(std::move(std::get<StagedFile>(staged)));
  return std::nullopt;
}

std::optional<std::string> OutputSet::commit() {
  if (!complete()) return std::string("internal error: an output was not produced");
  // Standard output and special files first: they cannot be taken back, so the regular files
  // are replaced only once every one of them was written (`-o a.exr -o -` with standard output
  // full keeps the old a.exr). Written with no lock: a FIFO without a reader may block here,
  // and an interrupt must still be able to end the process.
  for (Entry& e : entries_) {
    if (!e.bytes) continue;
    if (auto error = writeThrough(e.target, *e.bytes)) return error;
  }
  {
    // Every rename under the lock that the signal thread takes before removing temporaries: an
    // interrupt waits until the set is committed.
    auto held = TemporaryFiles::lock();
    for (Entry& e : entries_) {
      if (!e.staged) continue;
      if (auto error = e.staged->commit()) return error;
    }
  }
  entries_.clear();
  byRequested_.clear();
  return std::nullopt;
}

bool printError(const std::optional<std::string>& error) {
  if (error) std::fprintf(stderr, "error: %s\n", error->c_str());
  return error.has_value();
}

}  // namespace mxc::cli
