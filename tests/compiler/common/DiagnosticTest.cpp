// compiler/common/Diagnostic: what reaches a terminal, and how much of it.

#include <gtest/gtest.h>

#include "compiler/common/Diagnostic.h"

namespace mxc {
namespace {

TEST(Diagnostic, ControlCharactersAreEscaped) {
  SourceManager sources;
  const SourceFile& file = sources.add("x.mtlx", "<a b=\"\x1b[2J\xc2\x9b\xff\"/>\n");
  Diagnostic d{Severity::Error, {&file, 6}, "bad value \"\x1b[2J\xc2\x9b\xff\" and a\ttab"};
  // In the message: visible escapes. In the echoed line: one '?' per character, so the caret
  // stays under column 7.
  EXPECT_EQ(d.format(), "x.mtlx:1:7: error: bad value \"\\x1B[2J\\u009B\\xFF\" and a\ttab");
  EXPECT_EQ(d.formatWithSource(), d.format() + "\n 1 | <a b=\"?[2J??\"/>\n   |       ^");
}

TEST(Diagnostic, OnlyTheFirstMessagesAreKeptAndEachIsCut) {
  Diagnostics all;
  for (size_t i = 0; i < Diagnostics::kMaxKept + 50; ++i) all.error({}, "e");
  all.warning({}, "w");
  EXPECT_EQ(all.all().size(), Diagnostics::kMaxKept);
  EXPECT_EQ(all.errorCount(), Diagnostics::kMaxKept + 50) << "every error still counts";
  EXPECT_EQ(all.omittedErrors(), 50u);
  EXPECT_EQ(all.omittedWarnings(), 1u);
  EXPECT_NE(all.omittedSummary().find("50 more error(s), 1 more warning(s)"), std::string::npos);
  Diagnostics one;
  // A cut never splits a UTF-8 sequence: "é" is two bytes.
  std::string long_message;
  for (int i = 0; i < 1000; ++i) long_message += "\xc3\xa9";
  one.error({}, long_message);
  const std::string& kept = one.all().front().message;
  EXPECT_LT(kept.size(), Diagnostics::kMaxMessageBytes + 40);
  EXPECT_NE(kept.find("more bytes)"), std::string::npos);
  EXPECT_EQ(kept.substr(0, 4), "\xc3\xa9\xc3\xa9");
  EXPECT_EQ(kept.find("\xc3..."), std::string::npos);
}

}  // namespace
}  // namespace mxc
