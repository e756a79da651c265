#pragma once
/// \file
/// UTF-8 decoding and the character classes of XML 1.0 (Fifth Edition).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mxc::xml {

/// Where and why a text is not well-formed UTF-8 or holds a character XML forbids.
struct TextError {
  uint32_t offset = 0;
  std::string message;
};

/// Checks that `text` is valid UTF-8 (no overlong forms, no surrogates, nothing above
/// U+10FFFF) and that every character is an XML `Char` (§2.2: no C0 controls other than
/// tab, line feed and carriage return; no U+FFFE or U+FFFF). Linear, with an ASCII fast path.
std::optional<TextError> checkXmlText(std::string_view text);

/// Decodes the code point at `p` (the text must already have passed checkXmlText).
/// Returns the number of bytes it takes (1 to 4).
int decodeUtf8(const char* p, uint32_t& codePoint);

/// Appends the UTF-8 encoding of a valid code point.
void appendUtf8(std::string& out, uint32_t codePoint);

/// XML 1.0 §2.2 `Char`: the code points a document may contain.
bool isXmlChar(uint32_t codePoint);
/// XML 1.0 §2.3 `NameStartChar` and `NameChar`.
bool isNameStartChar(uint32_t codePoint);
bool isNameChar(uint32_t codePoint);

/// "U+00E9" style spelling of a code point for messages.
std::string codePointName(uint32_t codePoint);

}  // namespace mxc::xml
