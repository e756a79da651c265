#pragma once
/// \file
/// What every mxc command shares: sources, diagnostics and the node libraries.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "compiler/common/Diagnostic.h"
#include "compiler/inspect/Inspect.h"
#include "compiler/library/LibraryStack.h"

namespace mxc::cli {

/// Library options common to the commands.
struct LibraryOptions {
  std::vector<std::string> folders;  ///< --library DIR (repeatable), layered over the built-in library
  bool noBuiltin = false;            ///< --no-builtin: only the given folders
};

void addLibraryOptions(CLI::App& command, LibraryOptions& options);

/// Sources, diagnostics and libraries of one command run.
class Session {
 public:
  Session();
  /// Loads the libraries the options ask for; false when one of them has errors.
  bool loadLibraries(const LibraryOptions& options);
  /// Prints the diagnostics gathered so far to stderr (with source lines) and forgets them.
  void printDiagnostics();

  SourceManager sources;
  Diagnostics diagnostics;
  lib::LibraryStack libraries;
  std::vector<inspect::LibraryInfo> libraryInfo;

 private:
  size_t printed_ = 0;
};

}  // namespace mxc::cli
