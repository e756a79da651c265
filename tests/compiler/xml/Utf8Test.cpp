// Tests of UTF-8 checking and XML character classes.

#include "compiler/xml/Utf8.h"

#include <gtest/gtest.h>

namespace mxc::xml {
namespace {

TEST(Utf8, AcceptsEveryValidEncodingLength) {
  std::string text;
  for (uint32_t c : {0x41u, 0xE9u, 0x20ACu, 0x1F600u, 0x10FFFFu - 2u}) appendUtf8(text, c);
  EXPECT_FALSE(checkXmlText(text).has_value());
  uint32_t c;
  EXPECT_EQ(decodeUtf8(text.data() + 1, c), 2);
  EXPECT_EQ(c, 0xE9u);
  EXPECT_EQ(decodeUtf8(text.data() + 3, c), 3);
  EXPECT_EQ(c, 0x20ACu);
  EXPECT_EQ(decodeUtf8(text.data() + 6, c), 4);
  EXPECT_EQ(c, 0x1F600u);
}

TEST(Utf8, FastPathFindsAnErrorInsideALongAsciiRun) {
  std::string text(1000, 'a');
  text[777] = '\x02';
  auto error = checkXmlText(text);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->offset, 777u);
  text[777] = '\n';
  EXPECT_FALSE(checkXmlText(text).has_value());
}

TEST(Utf8, XmlCharacterClasses) {
  EXPECT_TRUE(isXmlChar(0x9));
  EXPECT_FALSE(isXmlChar(0x0));
  EXPECT_FALSE(isXmlChar(0xFFFF));
  EXPECT_TRUE(isNameStartChar(':'));
  EXPECT_FALSE(isNameStartChar('-'));
  EXPECT_TRUE(isNameChar('-'));
  EXPECT_TRUE(isNameStartChar(0x4E2D));  // a CJK ideograph
  EXPECT_FALSE(isNameStartChar(0xB7));
  EXPECT_TRUE(isNameChar(0xB7));
  EXPECT_EQ(codePointName(0x41), "U+0041");
}

}  // namespace
}  // namespace mxc::xml
