#pragma once
/// \file
/// Writing output files so that a reader never sees half of one.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace mxc::cli {

/// Writes `contents` to a temporary file beside `path` and renames it over `path` once it is
/// complete, so a failure (or a crash) leaves either the old file or none, never a partial one.
/// Returns an error message on failure.
std::optional<std::string> writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

/// A command's report: to stdout when `path` is empty or "-", else atomically to the file.
/// Returns false (with the error printed) when the file could not be written.
bool writeReport(const std::string& path, std::string_view contents);

}  // namespace mxc::cli
