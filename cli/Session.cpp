#include "cli/Session.h"

#include <cstdio>

#include <fmt/format.h>

namespace mxc::cli {

void addLibraryOptions(CLI::App& command, LibraryOptions& options) {
  command.add_option("--library", options.folders,
                     "Node library folder (every .mtlx under it) or file, layered over the built-in library; "
                     "repeatable, later ones shadow earlier definitions of the same name");
  command.add_flag("--no-builtin", options.noBuiltin, "Do not load mxc's built-in node library");
}

Session::Session() : libraries(sources, diagnostics) {}

bool Session::loadLibraries(const LibraryOptions& options) {
  const size_t before = diagnostics.errorCount();
  if (!options.noBuiltin) {
    libraries.addBuiltin();
    libraryInfo.push_back({"builtin", libraries.top().nodeDefCount()});
  }
  for (const std::string& folder : options.folders) {
    if (libraries.addFolder(folder)) libraryInfo.push_back({folder, libraries.top().nodeDefCount()});
  }
  if (libraries.empty()) {
    diagnostics.error({}, "no node library: --no-builtin needs at least one --library");
  }
  return diagnostics.errorCount() == before;
}

void Session::printDiagnostics() {
  const auto& all = diagnostics.all();
  for (; printed_ < all.size(); ++printed_) std::fprintf(stderr, "%s\n", all[printed_].formatWithSource().c_str());
}

}  // namespace mxc::cli
