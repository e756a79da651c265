#pragma once
/// \file
/// What every mxc command shares: sources, diagnostics and the node libraries.

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/OutputSet.h"
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

/// A CLI11 check that an option's number is finite, and >= 0 when `nonNegative` (CLI11's own
/// number checks let "nan" and "inf" through, and both parse as floats).
CLI::Validator finiteNumber(bool nonNegative);

/// Sources, diagnostics and libraries of one command run.
class Session {
 public:
  Session();
  /// Loads the libraries the options ask for; false when one of them has errors.
  bool loadLibraries(const LibraryOptions& options);
  /// Prints the diagnostics gathered so far to stderr (with source lines) and forgets them.
  void printDiagnostics();
  /// A usage error when an output of `outputs` is a file this session read (the document, an
  /// included document, a library file).
  std::optional<std::string> checkOutputsAreNotSources(const OutputSet& outputs) const;

  SourceManager sources;
  Diagnostics diagnostics;
  lib::LibraryStack libraries;
  std::vector<inspect::LibraryInfo> libraryInfo;

 private:
  size_t printed_ = 0;
  size_t omittedPrinted_ = 0;
};

}  // namespace mxc::cli
