#pragma once
/// \file
/// Our XML 1.0 parser: the subset MaterialX needs, strictly checked, in linear time.
///
/// Accepted: elements, attributes in either quote style, self-closing tags, text, CDATA,
/// comments, the XML declaration, processing instructions, a UTF-8 byte-order mark, the five
/// predefined entities and numeric character references.
/// Refused with a message: DTDs and entity declarations (no entity-expansion attacks),
/// encodings other than UTF-8, input above a size limit, nesting above a depth limit.
/// Whitespace-only text between elements is not kept.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "compiler/common/Diagnostic.h"
#include "compiler/xml/XmlDocument.h"

namespace mxc::xml {

/// Limits that keep hostile input from exhausting the machine.
struct ParseOptions {
  /// Largest accepted input. Offsets are 32-bit, so this stays below 4 GiB.
  size_t maxInputBytes = size_t{1} << 30;
  /// Deepest element nesting accepted (MaterialX documents nest about 4 deep).
  uint32_t maxDepth = 256;
  /// Most attributes on one element.
  uint32_t maxAttributes = 4096;
  /// Where given, a raw '<' inside an attribute value is read as written, with a warning added
  /// here; otherwise it is an error. It is not well-formed XML (XML 1.0 s. 3.1, AttValue), but
  /// MaterialX's parser accepts it and MaterialX's documents write it (`grid.<UDIM>.png`).
  std::vector<Diagnostic>* warnings = nullptr;
};

/// Parses the whole text of `source`. Throws CompileError, with file, line, column and a
/// message, at the first construct that is not well-formed. `source` must outlive the result.
Document parse(const SourceFile& source, const ParseOptions& options = {});

}  // namespace mxc::xml
