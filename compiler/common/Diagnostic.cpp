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

std::string Diagnostic::formatWithSource() const {
  std::string out = format();
  if (!location.valid()) return out;
  LineColumn lc = location.lineColumn();
  std::string_view text = location.file->lineText(lc.line);
  // Very long lines (minified files) are not echoed: the position is in the first line already.
  if (text.empty() || text.size() > 300) return out;
  std::string number = std::to_string(lc.line);
  out += "\n " + number + " | " + std::string(text) + "\n " + std::string(number.size(), ' ') + " | ";
  // The caret line keeps the tabs of the source so the caret lands under the column; any other
  // character (one code point, however many bytes) becomes one space.
  uint32_t column = 1;
  for (size_t i = 0; i < text.size() && column < lc.column; ++i) {
    const auto b = static_cast<unsigned char>(text[i]);
    if ((b & 0xC0) == 0x80) continue;
    out += b == '\t' ? '\t' : ' ';
    ++column;
  }
  out += '^';
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
