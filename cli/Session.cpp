#include "cli/Session.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "cli/Verbosity.h"

namespace mxc::cli {



bool Session::loadLibraries(const LibraryOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const bool ok = workspace.loadLibraries(!options.noBuiltin, options.folders);
  if (verbose()) {
    std::string layers;
    for (const auto& info : workspace.libraryInfo) {
      layers += fmt::format("{}{} ({} nodedefs)", layers.empty() ? "" : ", ", info.name, info.nodedefs);
    }
    detail("libraries {} loaded in {:.1f} ms", layers.empty() ? "none" : layers, millisecondsSince(start));
  }
  return ok;
}

void Session::printDiagnostics() {
  const Diagnostics& diagnostics = workspace.diagnostics;
  const auto& all = diagnostics.all();
  for (; printed_ < all.size(); ++printed_) {
    if (quiet() && all[printed_].severity != Severity::Error) continue;  // -q: errors only
    printLine(all[printed_].formatWithSource());
  }
  const size_t omitted = diagnostics.omittedErrors() + diagnostics.omittedWarnings();
  if (omitted > omittedPrinted_) {
    printLine(diagnostics.omittedSummary());
    omittedPrinted_ = omitted;
  }
}

void Session::printLine(const std::string& line) {
  if (capture) *capture += line + "\n";
  else std::fprintf(stderr, "%s\n", line.c_str());
}

std::optional<std::string> Session::checkOutputsAreNotSources(const OutputSet& outputs) const {
  // The built-in library's texts are not files and never match.
  for (const auto& file : workspace.sources.files()) {
    if (auto error = outputs.checkNotInput(file->path(), "a document this command reads")) return error;
  }
  return std::nullopt;
}

}  // namespace mxc::cli
