#pragma once
/// \file
/// Text from a document (a file name, a colour space, a material's name) quoted for where it
/// goes: a message, or a comment of generated code. A document's text may hold any character
/// an XML character reference can write (`&#10;` is a newline): raw, a newline in a `//`
/// comment of GLSL ends the comment, and the rest of the value becomes shader code; a trailing
/// backslash joins the next line to the comment (GLSL's line continuation).

#include <cstddef>
#include <string>
#include <string_view>

namespace mxc {

/// The length of the well-formed UTF-8 sequence at `text[i]` (i < text.size()), or 0 when it
/// is not one (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
size_t utf8SequenceLength(std::string_view text, size_t i);

/// `text` between double quotes, with `"` and `\` escaped by a backslash, and every control
/// character (U+0000 to U+001F, U+007F, and the C1 controls U+0080 to U+009F) and every byte
/// that is not UTF-8 written as a visible escape (\n, \r, \t, \xHH, \uHHHH). The result holds
/// no control character, no line break and no byte that is not UTF-8, and ends with `"`, so it
/// can stand in a `//` comment, a message or a JSON-less log line as one token.
std::string quotedValue(std::string_view text);

}  // namespace mxc
