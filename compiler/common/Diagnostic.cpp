#include "compiler/common/Diagnostic.h"

#include <fmt/format.h>

#include "compiler/common/Quote.h"

namespace mxc {

namespace {

/// Control characters of a document (an ESC sequence, a bell, a C1 control) and bytes that are
/// not UTF-8 must not reach a terminal raw: they would be obeyed or garble it, not be shown.
/// Each becomes a visible escape such as \x1B; tabs and line breaks stay. In an echoed source
/// line (`oneColumn`) each becomes a single '?' instead, so the caret under the column stays
/// aligned (the caret counts code points).
std::string printable(std::string_view text, bool oneColumn) {
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const size_t length = utf8SequenceLength(text, i);
    const bool c0 = (b < 0x20 && b != '\t' && b != '\n') || b == 0x7F;
    // C1 controls U+0080..U+009F, encoded in UTF-8 as C2 80..C2 9F.
    const bool c1 = length == 2 && b == 0xC2 && static_cast<unsigned char>(text[i + 1]) <= 0x9F;
    if (length == 0 || c0) {
      out += oneColumn ? std::string("?") : fmt::format("\\x{:02X}", b);
      ++i;
    } else if (c1) {
      out += oneColumn ? std::string("?") : fmt::format("\\u{:04X}", static_cast<unsigned char>(text[i + 1]));
      i += 2;
    } else {
      out.append(text.substr(i, length));
      i += length;
    }
  }
  return out;
}

/// At most `limit` bytes of `text`, cut at a character boundary, with what was left out said.
std::string capped(std::string text, size_t limit) {
  if (text.size() <= limit) return text;
  size_t cut = limit;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 sequence
  const size_t left = text.size() - cut;
  text.resize(cut);
  return text + fmt::format("... ({} more bytes)", left);
}

}  // namespace

std::string Diagnostic::format() const {
  std::string out;
  if (location.valid()) out += location.str() + ": ";
  switch (severity) {
    case Severity::Error: out += "error: "; break;
    case Severity::Warning: out += "warning: "; break;
    case Severity::Note: out += "note: "; break;
  }
  out += printable(message, false);
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
  out += "\n " + number + " | " + printable(text, true) + "\n " + std::string(number.size(), ' ') + " | ";
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
  if (items_.size() >= kMaxKept) {
    ++(diagnostic.severity == Severity::Error ? omittedErrors_ : diagnostic.severity == Severity::Warning ? omittedWarnings_
                                                                                                       : omittedNotes_);
    return;
  }
  // A message quoting a 10 MB attribute value is cut: the position already says where it is.
  diagnostic.message = capped(std::move(diagnostic.message), kMaxMessageBytes);
  items_.push_back(std::move(diagnostic));
}

std::string Diagnostics::omittedSummary() const {
  if (omittedErrors_ + omittedWarnings_ + omittedNotes_ == 0) return {};
  return fmt::format("{} more error(s), {} more warning(s) and {} more note(s) not shown (only the first {} are kept)",
                     omittedErrors_, omittedWarnings_, omittedNotes_, kMaxKept);
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
