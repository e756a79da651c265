#pragma once
/// \file
/// What every mxc command shares: the compiler's workspace (sources, diagnostics, libraries),
/// the library options, and printing the diagnostics as they come.

#include <optional>
#include <string>
#include <vector>

#include "cli/OutputSet.h"
#include "compiler/driver/Compiler.h"

namespace mxc::cli {

/// Library options common to the commands.
struct LibraryOptions {
  std::vector<std::string> folders;  ///< --library DIR (repeatable), layered over the built-in library
  bool noBuiltin = false;            ///< --no-builtin: only the given folders
};


/// The workspace of one command run, and what of its diagnostics has been printed.
class Session {
 public:
  /// Loads the libraries the options ask for; false when one of them has errors.
  bool loadLibraries(const LibraryOptions& options);
  /// Prints the diagnostics not printed yet to stderr (with source lines), then a count of
  /// those not kept (Diagnostics::kMaxKept).
  void printDiagnostics();
  /// Prints a line of the command's own (an error or a summary about the document) to stderr,
  /// or into the capture.
  void printLine(const std::string& line);
  /// Where the session's messages go instead of stderr when set: a batch compiles documents at
  /// once and prints each one's messages together when it is done.
  std::string* capture = nullptr;
  /// A usage error when an output of `outputs` is a file this session read (the document, an
  /// included document, a library file).
  std::optional<std::string> checkOutputsAreNotSources(const OutputSet& outputs) const;

  Workspace workspace;

 private:
  size_t printed_ = 0;
  size_t omittedPrinted_ = 0;
};

}  // namespace mxc::cli
