#pragma once
// The depfile `mxc compile --depfile` writes: one Makefile rule from every file written to every
// file read, in the dialect both GNU Make and Ninja (1.11, Debian 12's) read the same way.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mxc::cli {

/// `path` as a word of a Makefile rule that Make and Ninja both read back as `path`, or nothing
/// (with `error` saying which character and why) when no spelling reads the same in both.
std::optional<std::string> depfileWord(const std::string& path, std::string& error);

/// The rule: `written` (in order) depend on `read` (made absolute, sorted, each once). Nothing,
/// with `error` naming the path, when a path cannot be spelled for both tools.
std::optional<std::string> depfileText(const std::vector<std::filesystem::path>& written,
                                       std::vector<std::filesystem::path> read, std::string& error);

}  // namespace mxc::cli
