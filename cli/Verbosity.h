#pragma once
/// \file
/// How much the command line says: `-q` (errors only), the default, or `-v` (what each stage
/// did and how long it took). One setting for the process: every command prints through it.

#include <chrono>
#include <string>

#include <fmt/format.h>

namespace mxc::cli {

enum class Verbosity { Quiet, Normal, Verbose };

Verbosity verbosity();
void setVerbosity(Verbosity level);

inline bool quiet() { return verbosity() == Verbosity::Quiet; }
inline bool verbose() { return verbosity() == Verbosity::Verbose; }

/// With -v: "mxc: LINE" on stderr (beside the diagnostics, away from a report on stdout).
void detailLine(const std::string& line);
template <typename... Args>
void detail(fmt::format_string<Args...> format, Args&&... args) {
  if (verbose()) detailLine(fmt::format(format, std::forward<Args>(args)...));
}

/// Milliseconds since `start`, for -v's timings.
inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mxc::cli
