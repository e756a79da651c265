#include "cli/Session.h"

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

namespace mxc::cli {

void addLibraryOptions(CLI::App& command, LibraryOptions& options) {
  command.add_option("--library", options.folders,
                     "Node library folder (every .mtlx under it) or file, layered over the built-in library; "
                     "repeatable, later ones shadow earlier definitions of the same name");
  command.add_flag("--no-builtin", options.noBuiltin, "Do not load mxc's built-in node library");
}

CLI::Validator finiteNumber(bool nonNegative) {
  return CLI::Validator(
      [nonNegative](std::string& text) -> std::string {
        size_t used = 0;
        double v = 0.0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          return fmt::format("'{}' is not a number", text);
        }
        if (used != text.size()) return fmt::format("'{}' is not a number", text);
        if (!std::isfinite(v)) return fmt::format("'{}' is not a finite number", text);
        if (nonNegative && v < 0.0) return fmt::format("'{}' is negative", text);
        return {};
      },
      nonNegative ? "NUMBER >= 0" : "NUMBER");
}

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
