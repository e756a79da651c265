#include "cli/OutputSet.h"

#include <cstdio>

#include <fmt/format.h>

namespace mxc::cli {

namespace fs = std::filesystem;

namespace {

/// The same target: one existing file, or one path (absolute, normalised) that does not exist
/// yet. Standard output counts as one target too.
bool sameTarget(const OutputTarget& a, const OutputTarget& b) {
  using Kind = OutputTarget::Kind;
  if (a.kind == Kind::Standard || b.kind == Kind::Standard) return a.kind == b.kind;
  if (sameExistingFile(a.path, b.path)) return true;
  std::error_code ec;
  const fs::path pa = fs::weakly_canonical(fs::absolute(a.path), ec);
  const fs::path pb = fs::weakly_canonical(fs::absolute(b.path), ec);
  return pa == pb;
}

}  // namespace

std::optional<std::string> OutputSet::declare(const fs::path& path, const std::string& option) {
  auto resolved = resolveOutput(path);
  if (auto* error = std::get_if<std::string>(&resolved)) return fmt::format("{}: {}", option, *error);
  entries_.push_back({std::move(std::get<OutputTarget>(resolved)), option, std::nullopt, std::nullopt});
  return std::nullopt;
}

std::optional<std::string> OutputSet::checkDistinct() const {
  for (size_t i = 0; i < entries_.size(); ++i) {
    for (size_t k = 0; k < i; ++k) {
      const Entry &a = entries_[k], &b = entries_[i];
      if (b.target.kind == OutputTarget::Kind::Special || !sameTarget(a.target, b.target)) continue;
      return fmt::format("{} '{}' and {} '{}' name the same file: one would overwrite the other", a.option,
                         a.target.requested.string(), b.option, b.target.requested.string());
    }
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
  for (Entry& e : entries_) {
    if (e.target.requested == path) return &e;
  }
  return nullptr;
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
  {
    // Every rename under the lock that the signal thread takes before removing temporaries: an
    // interrupt waits until the set is committed.
    auto held = TemporaryFiles::lock();
    for (Entry& e : entries_) {
      if (!e.staged) continue;
      if (auto error = e.staged->commit()) return error;
    }
  }
  // Written after the files, with no lock: a FIFO without a reader may block here, and an
  // interrupt must still be able to end the process.
  for (Entry& e : entries_) {
    if (!e.bytes) continue;
    if (auto error = writeThrough(e.target, *e.bytes)) return error;
  }
  entries_.clear();
  return std::nullopt;
}

bool printError(const std::optional<std::string>& error) {
  if (error) std::fprintf(stderr, "error: %s\n", error->c_str());
  return error.has_value();
}

}  // namespace mxc::cli
