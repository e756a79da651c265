#include "cli/Session.h"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

namespace mxc::cli {



bool Session::loadLibraries(const LibraryOptions& options) {
  return workspace.loadLibraries(!options.noBuiltin, options.folders);
}

void Session::printDiagnostics() {
  const Diagnostics& diagnostics = workspace.diagnostics;
  const auto& all = diagnostics.all();
  for (; printed_ < all.size(); ++printed_) std::fprintf(stderr, "%s\n", all[printed_].formatWithSource().c_str());
  const size_t omitted = diagnostics.omittedErrors() + diagnostics.omittedWarnings();
  if (omitted > omittedPrinted_) {
    std::fprintf(stderr, "%s\n", diagnostics.omittedSummary().c_str());
    omittedPrinted_ = omitted;
  }
}

std::optional<std::string> Session::checkOutputsAreNotSources(const OutputSet& outputs) const {
  // The built-in library's texts are not files and never match.
  for (const auto& file : workspace.sources.files()) {
    if (auto error = outputs.checkNotInput(file->path(), "a document this command reads")) return error;
  }
  return std::nullopt;
}

}  // namespace mxc::cli
