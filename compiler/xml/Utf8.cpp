#include "compiler/xml/Utf8.h"

#include <cstring>

#include <fmt/format.h>

namespace mxc::xml {

bool isXmlChar(uint32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
         (c >= 0x10000 && c <= 0x10FFFF);
}

bool isNameStartChar(uint32_t c) {
  if (c < 0x80) return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':';
  return (c >= 0xC0 && c <= 0xD6) || (c >= 0xD8 && c <= 0xF6) || (c >= 0xF8 && c <= 0x2FF) ||
         (c >= 0x370 && c <= 0x37D) || (c >= 0x37F && c <= 0x1FFF) || (c >= 0x200C && c <= 0x200D) ||
         (c >= 0x2070 && c <= 0x218F) || (c >= 0x2C00 && c <= 0x2FEF) || (c >= 0x3001 && c <= 0xD7FF) ||
         (c >= 0xF900 && c <= 0xFDCF) || (c >= 0xFDF0 && c <= 0xFFFD) || (c >= 0x10000 && c <= 0xEFFFF);
}

bool isNameChar(uint32_t c) {
  if (c < 0x80) return isNameStartChar(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
  return isNameStartChar(c) || c == 0xB7 || (c >= 0x300 && c <= 0x36F) || (c >= 0x203F && c <= 0x2040);
}

std::string codePointName(uint32_t c) { return fmt::format("U+{:04X}", c); }

int decodeUtf8(const char* p, uint32_t& codePoint) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  if (u[0] < 0x80) {
    codePoint = u[0];
    return 1;
  }
  if (u[0] < 0xE0) {
    codePoint = ((u[0] & 0x1Fu) << 6) | (u[1] & 0x3Fu);
    return 2;
  }
  if (u[0] < 0xF0) {
    codePoint = ((u[0] & 0x0Fu) << 12) | ((u[1] & 0x3Fu) << 6) | (u[2] & 0x3Fu);
    return 3;
  }
  codePoint = ((u[0] & 0x07u) << 18) | ((u[1] & 0x3Fu) << 12) | ((u[2] & 0x3Fu) << 6) | (u[3] & 0x3Fu);
  return 4;
}

void appendUtf8(std::string& out, uint32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

namespace {

// True when any byte of the word is >= 0x80 or < 0x20 (the cases the slow path must look at).
// Bit trick (Hacker's Delight 6-1): (w - 0x20..) & ~w & 0x80.. flags bytes below 0x20.
inline bool needsSlowPath(uint64_t w) {
  constexpr uint64_t kOnes = 0x0101010101010101ull;
  constexpr uint64_t kHigh = 0x8080808080808080ull;
  return ((w & kHigh) | ((w - kOnes * 0x20) & ~w & kHigh)) != 0;
}

}  // namespace

std::optional<TextError> checkXmlText(std::string_view text) {
  const auto* u = reinterpret_cast<const unsigned char*>(text.data());
  const size_t n = text.size();
  size_t i = 0;
  while (i < n) {
    if (i + 8 <= n) {
      uint64_t w;
      std::memcpy(&w, u + i, 8);
      if (!needsSlowPath(w)) {
        i += 8;
        continue;
      }
    }
    const unsigned char b = u[i];
    const auto at = static_cast<uint32_t>(i);
    if (b < 0x80) {
      if (b < 0x20 && b != '\t' && b != '\n' && b != '\r') {
        return TextError{at, fmt::format("character {} (a control character) is not allowed in XML", codePointName(b))};
      }
      ++i;
      continue;
    }
    int length;
    uint32_t minimum;
    uint32_t c;
    if (b >= 0xC2 && b <= 0xDF) {
      length = 2, minimum = 0x80, c = b & 0x1Fu;
    } else if (b >= 0xE0 && b <= 0xEF) {
      length = 3, minimum = 0x800, c = b & 0x0Fu;
    } else if (b >= 0xF0 && b <= 0xF4) {
      length = 4, minimum = 0x10000, c = b & 0x07u;
    } else if (b == 0xC0 || b == 0xC1) {
      return TextError{at, fmt::format("invalid UTF-8: byte 0x{:02X} starts an overlong encoding", b)};
    } else if (b >= 0x80 && b <= 0xBF) {
      return TextError{at, fmt::format("invalid UTF-8: unexpected continuation byte 0x{:02X}", b)};
    } else {
      return TextError{at, fmt::format("invalid UTF-8: byte 0x{:02X} cannot start a character", b)};
    }
    if (i + static_cast<size_t>(length) > n) {
      return TextError{at, "invalid UTF-8: the text ends inside a multi-byte character"};
    }
    for (int k = 1; k < length; ++k) {
      const unsigned char cont = u[i + static_cast<size_t>(k)];
      if ((cont & 0xC0) != 0x80) {
        return TextError{at, fmt::format("invalid UTF-8: byte 0x{:02X} at position {} of a {}-byte character is "
                                         "not a continuation byte",
                                         cont, k + 1, length)};
      }
      c = (c << 6) | (cont & 0x3Fu);
    }
    if (c < minimum) return TextError{at, "invalid UTF-8: overlong encoding of " + codePointName(c)};
    if (c >= 0xD800 && c <= 0xDFFF) return TextError{at, "invalid UTF-8: encoded surrogate " + codePointName(c)};
    if (c > 0x10FFFF) return TextError{at, "invalid UTF-8: code point above U+10FFFF"};
    if (!isXmlChar(c)) return TextError{at, "character " + codePointName(c) + " is not allowed in XML"};
    i += static_cast<size_t>(length);
  }
  return std::nullopt;
}

}  // namespace mxc::xml
