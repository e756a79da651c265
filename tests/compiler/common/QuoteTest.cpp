// quotedValue() (compiler/common/Quote.h): text from a document, made safe for a `//` comment of
// generated code and for a message, tested on every control character and on bytes that are
// not UTF-8.

#include <gtest/gtest.h>

#include <string>

#include "compiler/common/Quote.h"

namespace mxc {
namespace {

/// True when `s` could end a `//` comment or a message line early or act on a terminal: a
/// C0 or C1 control, DEL, or a byte that is not UTF-8.
bool holdsRawControlOrBadByte(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    const auto b = static_cast<unsigned char>(s[i]);
    const size_t length = utf8SequenceLength(s, i);
    if (length == 0 || b < 0x20 || b == 0x7F) return true;
    if (length == 2 && b == 0xC2 && static_cast<unsigned char>(s[i + 1]) <= 0x9F) return true;
    i += length;
  }
  return false;
}

TEST(Quote, EveryControlCharacterBecomesAVisibleEscape) {
  for (int c = 0; c < 0x20; ++c) {
    const std::string text = std::string("a") + static_cast<char>(c) + "b";
    const std::string q = quotedValue(text);
    EXPECT_FALSE(holdsRawControlOrBadByte(q)) << c;
    EXPECT_EQ(q.front(), '"');
    EXPECT_EQ(q.back(), '"');
    const std::string expected = c == '\n' ? "\\n" : c == '\r' ? "\\r" : c == '\t' ? "\\t"
                                 : std::string("\\x") + "0123456789ABCDEF"[c >> 4] + "0123456789ABCDEF"[c & 15];
    EXPECT_EQ(q, "\"a" + expected + "b\"") << c;
  }
  EXPECT_EQ(quotedValue(std::string("\x7F", 1)), "\"\\x7F\"");
  EXPECT_EQ(quotedValue(std::string("\0", 1)), "\"\\x00\"");
  for (int c = 0x80; c <= 0x9F; ++c) {  // C1 controls, U+0080 to U+009F
    const std::string text = std::string("\xC2") + static_cast<char>(c);
    EXPECT_FALSE(holdsRawControlOrBadByte(quotedValue(text))) << c;
  }
  EXPECT_EQ(quotedValue("\xC2\x85"), "\"\\u0085\"");
}

TEST(Quote, QuotesAndBackslashesAreEscapedSoNothingEndsWithALineContinuation) {
  EXPECT_EQ(quotedValue("c:\\dir\\"), "\"c:\\\\dir\\\\\"");
  EXPECT_EQ(quotedValue("say \"hi\""), "\"say \\\"hi\\\"\"");
  EXPECT_EQ(quotedValue(""), "\"\"");
}

TEST(Quote, UnicodeStaysAndBytesThatAreNotUtf8AreEscaped) {
  EXPECT_EQ(quotedValue("mat\xC3\xA9riau \xE2\x82\xAC \xF0\x9F\x98\x80"), "\"mat\xC3\xA9riau \xE2\x82\xAC \xF0\x9F\x98\x80\"");
  EXPECT_EQ(quotedValue("\xFF\xC3"), "\"\\xFF\\xC3\"");            // a stray byte and a cut sequence
  EXPECT_EQ(quotedValue("\xED\xA0\x80"), "\"\\xED\\xA0\\x80\"");   // a surrogate
  EXPECT_EQ(quotedValue("\xC0\xAF"), "\"\\xC0\\xAF\"");            // an overlong '/'
  // Every single byte, alone: the result is always printable, one line, and quoted.
  for (int b = 0; b < 256; ++b) {
    const std::string q = quotedValue(std::string(1, static_cast<char>(b)));
    EXPECT_FALSE(holdsRawControlOrBadByte(q)) << b;
    EXPECT_EQ(q.back(), '"') << b;
  }
}

}  // namespace
}  // namespace mxc
