#include "compiler/common/Diagnostic.h"

namespace mxc {

std::string Diagnostic::format() const {
  std::string out;
  if (location.valid()) out += location.str() + ": ";
  switch (severity) {
    case Severity::Error: out += "error: "; break;
    case Severity::Warning: out += "warning: "; break;
    case Severity::Note: out += "note: "; break;
  }
  out += message;
  return out;
}

void Diagnostics::add(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::Error) ++errorCount_;
  items_.push_back(std::move(diagnostic));
}

void Diagnostics::error(SourceLocation location, std::string message) {
  add({Severity::Error, location, std::move(message)});
}

void Diagnostics::warning(SourceLocation location, std::string message) {
  add({Severity::Warning, location, std::move(message)});
}

void Diagnostics::note(SourceLocation location, std::string message) {
  add({Severity::Note, location, std::move(message)});
}

std::string Diagnostics::format() const {
  std::string out;
  for (const Diagnostic& d : items_) out += d.format() + "\n";
  return out;
}

CompileError::CompileError(Diagnostic diagnostic)
    : std::runtime_error(diagnostic.format()), diagnostic_(std::move(diagnostic)) {}

}  // namespace mxc
