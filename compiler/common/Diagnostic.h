#pragma once
/// \file
/// Errors and warnings with the source position they are about.

#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/common/SourceFile.h"

namespace mxc {

enum class Severity { Error, Warning, Note };

/// One message about the input. `location` names file, line and column when known.
struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLocation location;
  std::string message;

  /// "file:line:column: error: message" (the position is left out when unknown).
  std::string format() const;
  /// format() followed, when the position is known, by the source line and a caret under
  /// the column, as compilers print them for a person at a terminal.
  std::string formatWithSource() const;
};

/// Collects the messages of a stage. A stage keeps going after an error where it can,
/// so a user sees every problem of a document in one run. A document with a million errors
/// would print hundreds of megabytes: only the first kMaxKept messages are kept (the rest are
/// counted), and a message is cut at kMaxMessageBytes.
class Diagnostics {
 public:
  static constexpr size_t kMaxKept = 200;
  static constexpr size_t kMaxMessageBytes = 1000;

  void error(SourceLocation location, std::string message);
  void warning(SourceLocation location, std::string message);
  void note(SourceLocation location, std::string message);
  void add(Diagnostic diagnostic);

  bool hasErrors() const { return errorCount_ > 0; }
  size_t errorCount() const { return errorCount_; }
  const std::vector<Diagnostic>& all() const { return items_; }
  /// Every message, one per line, in the order they were reported.
  std::string format() const;
  /// Messages counted but not kept, by severity.
  size_t omittedErrors() const { return omittedErrors_; }
  size_t omittedWarnings() const { return omittedWarnings_; }
  /// "N more error(s), ... not shown", or "" when every message was kept.
  std::string omittedSummary() const;

 private:
  std::vector<Diagnostic> items_;
  size_t errorCount_ = 0;
  size_t omittedErrors_ = 0;
  size_t omittedWarnings_ = 0;
  size_t omittedNotes_ = 0;
};

/// Thrown by stages that cannot continue after an error (the XML parser stops at the
/// first malformed construct, as XML requires).
class CompileError : public std::runtime_error {
 public:
  explicit CompileError(Diagnostic diagnostic);
  const Diagnostic& diagnostic() const { return diagnostic_; }

 private:
  Diagnostic diagnostic_;
};

}  // namespace mxc
