// Tests of the XML parser: what it accepts, what it builds, and the exact position and
// message of every error it reports.

#include "compiler/xml/XmlParser.h"

#include <gtest/gtest.h>

#include <string>

namespace mxc::xml {
namespace {

/// Parses `text` as a document named "test.xml"; the SourceFile is kept alive with the result.
struct Parsed {
  std::unique_ptr<SourceFile> source;
  Document document;
};

Parsed parseText(std::string text, const ParseOptions& options = {}) {
  auto source = std::make_unique<SourceFile>("test.xml", std::move(text));
  Document document = parse(*source, options);
  return Parsed{std::move(source), std::move(document)};
}

TEST(XmlParser, ElementsAttributesAndNesting) {
  Parsed p = parseText(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<materialx version=\"1.39\">\n"
      "  <nodegraph name='NG'>\n"
      "    <add name=\"a\" type=\"float\"/>\n"
      "    <output name=\"out\" type=\"float\" nodename=\"a\" />\n"
      "  </nodegraph>\n"
      "</materialx>\n");
  Element root = p.document.root();
  EXPECT_EQ(root.name(), "materialx");
  EXPECT_EQ(root.attribute("version"), "1.39");
  EXPECT_FALSE(root.attribute("colorspace").has_value());
  auto graphs = root.children();
  ASSERT_EQ(graphs.size(), 1u);
  EXPECT_EQ(graphs[0].attribute("name"), "NG");
  auto nodes = graphs[0].children();
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_EQ(nodes[0].name(), "add");
  EXPECT_EQ(nodes[1].attribute("nodename"), "a");
  EXPECT_EQ(nodes[1].parent().name(), "nodegraph");
  EXPECT_EQ(nodes[0].location().lineColumn().line, 4u);
  EXPECT_EQ(nodes[0].location().lineColumn().column, 5u);
  EXPECT_EQ(nodes[0].location().str(), "test.xml:4:5");
}

TEST(XmlParser, AttributeLocationsPointAtNameAndValue) {
  Parsed p = parseText("<a\n  b=\"xyz\"/>");
  const Attribute* b = p.document.root().findAttribute("b");
  ASSERT_NE(b, nullptr);
  LineColumn name = p.source->lineColumn(b->nameOffset);
  LineColumn value = p.source->lineColumn(b->valueOffset);
  EXPECT_EQ(name.line, 2u);
  EXPECT_EQ(name.column, 3u);
  EXPECT_EQ(value.column, 6u);
  EXPECT_FALSE(b->decoded);
}

TEST(XmlParser, EntitiesAndCharacterReferences) {
  Parsed p = parseText("<a v=\"&lt;&gt;&amp;&apos;&quot;&#65;&#x42;&#xe9;&#x1F600;\">x &amp; y&#10;</a>");
  EXPECT_EQ(p.document.root().attribute("v"), "<>&'\"AB\xC3\xA9\xF0\x9F\x98\x80");
  EXPECT_TRUE(p.document.root().findAttribute("v")->decoded);
  EXPECT_EQ(p.document.root().text(), "x & y\n");
}

TEST(XmlParser, AttributeValueNormalisation) {
  // XML 1.0 §3.3.3: tab, line feed and CR LF each become one space; a reference keeps its character.
  Parsed p = parseText("<a v=\"1,\t2,\r\n3,\n4&#10;\"/>");
  EXPECT_EQ(p.document.root().attribute("v"), "1, 2, 3, 4\n");
}

TEST(XmlParser, BothQuoteStylesAndQuotesInside) {
  Parsed p = parseText("<a x='say \"hi\"' y=\"it's\"/>");
  EXPECT_EQ(p.document.root().attribute("x"), "say \"hi\"");
  EXPECT_EQ(p.document.root().attribute("y"), "it's");
}

// A raw '<' in an attribute value is not well-formed, but MaterialX writes and reads it
// (`grid.<UDIM>.png`): with a place for warnings it is kept as written, each one reported at its
// line and column, in the fast path (nothing else to decode) and in the decoding one.
TEST(XmlParser, RawLessThanInAnAttributeIsKeptWithAWarningWhereAsked) {
  std::vector<Diagnostic> warnings;
  ParseOptions options;
  options.warnings = &warnings;
  Parsed p = parseText("<a x=\"grid.<UDIM>.png\"\n   y=\"&amp;<b>\"/>", options);
  EXPECT_EQ(p.document.root().attribute("x"), "grid.<UDIM>.png");
  EXPECT_EQ(p.document.root().attribute("y"), "&<b>");
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].severity, Severity::Warning);
  EXPECT_NE(warnings[0].message.find("'<' in the value of attribute 'x'"), std::string::npos) << warnings[0].message;
  EXPECT_EQ(warnings[0].location.lineColumn().line, 1u);
  EXPECT_EQ(warnings[0].location.lineColumn().column, 12u);
  EXPECT_EQ(warnings[1].location.lineColumn().line, 2u);
  EXPECT_EQ(warnings[1].location.lineColumn().column, 12u);
  // Without the place, the strict parser's error (XmlMalformed.LessThanInAttribute).
  EXPECT_THROW(parseText("<a x=\"1<2\"/>"), CompileError);
}

TEST(XmlParser, CommentsCDataAndProcessingInstructions) {
  Parsed p = parseText(
      "<!-- before --><?pi data?>\n<a><!-- c1 --><![CDATA[<raw> & ]] text]]><?target some data?></a><!-- after -->");
  Element a = p.document.root();
  EXPECT_EQ(a.text(), "<raw> & ]] text");
  std::vector<uint32_t> kids = a.childNodes();
  ASSERT_EQ(kids.size(), 3u);
  EXPECT_EQ(p.document.node(kids[0]).kind, NodeKind::Comment);
  EXPECT_EQ(p.document.node(kids[0]).value, " c1 ");
  EXPECT_EQ(p.document.node(kids[1]).kind, NodeKind::CData);
  EXPECT_EQ(p.document.node(kids[2]).kind, NodeKind::ProcessingInstruction);
  EXPECT_EQ(p.document.node(kids[2]).name, "target");
  EXPECT_EQ(p.document.node(kids[2]).value, "some data");
}

TEST(XmlParser, ByteOrderMarkAndUnicodeNames) {
  Parsed p = parseText("\xEF\xBB\xBF<caf\xC3\xA9 na\xC3\xAFve=\"1\"><x\xE2\x80\xBF/></caf\xC3\xA9>");
  EXPECT_EQ(p.document.root().name(), "caf\xC3\xA9");
  EXPECT_EQ(p.document.root().attribute("na\xC3\xAFve"), "1");
  // Columns count code points, and the byte-order mark is not a column: the child starts after
  // the 16 characters of <café naïve="1">.
  EXPECT_EQ(p.document.root().children()[0].location().lineColumn().column, 17u);
}

TEST(XmlParser, CarriageReturnLineEndsInText) {
  Parsed p = parseText("<a>\r\nx\ry\r\n</a>");
  EXPECT_EQ(p.document.root().text(), "\nx\ny\n");
}

TEST(XmlParser, WhitespaceBetweenElementsIsNotKept) {
  Parsed p = parseText("<a>\n  <b/>\n  <c/>\n</a>");
  EXPECT_EQ(p.document.root().childNodes().size(), 2u);
}

TEST(XmlParser, ManyAttributesUseTheHashedDuplicateCheck) {
  std::string text = "<a";
  for (int i = 0; i < 100; ++i) text += " a" + std::to_string(i) + "=\"" + std::to_string(i) + "\"";
  text += "/>";
  Parsed p = parseText(text);
  EXPECT_EQ(p.document.root().attributes().size(), 100u);
  EXPECT_EQ(p.document.root().attribute("a99"), "99");
  text.insert(text.size() - 2, " a50=\"x\"");
  EXPECT_THROW(parseText(text), CompileError);
}

TEST(XmlParser, DeepNestingWithinTheLimitParses) {
  std::string text;
  for (int i = 0; i < 200; ++i) text += "<e>";
  for (int i = 0; i < 200; ++i) text += "</e>";
  EXPECT_NO_THROW(parseText(text));
}

// ---------------------------------------------------------------------------------------------
// Malformed input: each case gives the text, the expected line and column, and a part of the
// message a person reads.

struct Malformed {
  const char* name;
  std::string text;
  uint32_t line;
  uint32_t column;
  const char* message;
};

void PrintTo(const Malformed& m, std::ostream* os) { *os << m.name; }

class XmlMalformed : public ::testing::TestWithParam<Malformed> {};

TEST_P(XmlMalformed, ReportsPositionAndMessage) {
  const Malformed& m = GetParam();
  ParseOptions options;
  options.maxDepth = 8;
  options.maxAttributes = 4;
  SourceFile source("test.xml", m.text);  // outlives the error, whose location points into it
  try {
    parse(source, options);
    FAIL() << "expected an error for: " << m.text;
  } catch (const CompileError& e) {
    const Diagnostic& d = e.diagnostic();
    EXPECT_EQ(d.location.file->path(), "test.xml");
    LineColumn lc = d.location.lineColumn();
    EXPECT_EQ(lc.line, m.line) << d.format();
    EXPECT_EQ(lc.column, m.column) << d.format();
    EXPECT_NE(d.message.find(m.message), std::string::npos) << "message was: " << d.message;
    EXPECT_EQ(std::string(e.what()).rfind("test.xml:", 0), 0u) << e.what();
  }
}

const Malformed kMalformed[] = {
    {"Empty", "", 1, 1, "the document is empty"},
    {"OnlyWhitespace", "  \n ", 2, 2, "no root element"},
    {"OnlyComment", "<!-- x -->", 1, 11, "no root element"},
    {"TextBeforeRoot", "hello <a/>", 1, 1, "text before the root element"},
    {"TextAfterRoot", "<a/>\n oops", 2, 2, "text after the root element"},
    {"TwoRoots", "<a/><b/>", 1, 5, "exactly one root element"},
    {"MismatchedEndTag", "<a>\n  <b>\n  </c>\n</a>", 3, 3, "mismatched end tag </c>: the open element is <b> (opened at line 2, column 3)"},
    {"UnclosedElement", "<a>\n  <b>\n", 3, 1, "<b> (opened at line 2, column 3) is not closed"},
    {"UnclosedRoot", "<materialx version=\"1.39\">", 1, 27, "<materialx> (opened at line 1, column 1) is not closed"},
    {"EndTagWithoutStart", "<a></a></b>", 1, 8, "exactly one root element"},
    {"UnclosedStartTagAtEof", "<a b=\"1\"", 1, 1, "start tag <a> is not closed"},
    {"StartTagInterruptedByTag", "<a b=\"1\" <c/>", 1, 10, "start tag <a> is not closed: found '<'"},
    {"DuplicateAttribute", "<a x=\"1\" y=\"2\" x=\"3\"/>", 1, 16, "duplicate attribute 'x' on <a>"},
    {"UnquotedAttribute", "<a x=1/>", 1, 6, "must be in quotes, found '1'"},
    {"MissingEquals", "<a x \"1\"/>", 1, 6, "expected '=' after the attribute name 'x'"},
    {"AttributesNotSeparated", "<a x=\"1\"y=\"2\"/>", 1, 9, "must be separated by whitespace"},
    {"UnclosedAttributeValue", "<a x=\"1/>\n", 1, 6, "value of attribute 'x' is not closed"},
    {"LessThanInAttribute", "<a x=\"1<2\"/>", 1, 8, "'<' is not allowed in the value of attribute 'x'"},
    {"BadElementNameDigit", "<1a/>", 1, 1, "stray '<'"},
    {"StrayLessThanInText", "<a>1 < 2</a>", 1, 6, "stray '<': expected an element name"},
    {"BadAttributeNameStart", "<a -x=\"1\"/>", 1, 4, "unexpected '-' in the start tag <a>"},
    {"SlashWithoutGreater", "<a/ >", 1, 3, "expected '>' after '/'"},
    {"EndTagGarbage", "<a></a x>", 1, 8, "expected '>' to close the end tag </a>"},
    {"BareAmpersand", "<a>fish & chips</a>", 1, 9, "'&' must be written as '&amp;'"},
    {"UnknownEntity", "<a>&nbsp;</a>", 1, 4, "unknown entity '&nbsp;'"},
    {"EntityWithoutSemicolon", "<a x=\"&amp\"/>", 1, 7, "entity reference '&amp' is missing its ';'"},
    {"CharRefNoDigits", "<a>&#;</a>", 1, 4, "needs digits"},
    {"CharRefHexNoDigits", "<a>&#x;</a>", 1, 4, "needs hexadecimal digits"},
    {"CharRefToNul", "<a>&#0;</a>", 1, 4, "names U+0000, which XML does not allow"},
    {"CharRefToSurrogate", "<a>&#xD800;</a>", 1, 4, "names U+D800"},
    {"CharRefTooLarge", "<a>&#x110000;</a>", 1, 4, "above U+10FFFF"},
    {"CharRefHugeDecimal", "<a>&#99999999999999999999;</a>", 1, 4, "above U+10FFFF"},
    {"CharRefMissingSemicolon", "<a>&#65 </a>", 1, 8, "missing its ';'"},
    {"Doctype", "<?xml version=\"1.0\"?>\n<!DOCTYPE lolz [<!ENTITY lol \"lol\">]>\n<a/>", 2, 1, "<!DOCTYPE> is not supported"},
    {"EntityDeclarationInside", "<a><!ENTITY x \"y\"></a>", 1, 4, "<!ENTITY> is not supported"},
    {"UnknownBangMarkup", "<a><!FOO></a>", 1, 4, "unexpected '<!'"},
    {"CommentDoubleDash", "<a><!-- a -- b --></a>", 1, 11, "'--' is not allowed inside a comment"},
    {"UnclosedComment", "<a><!-- never", 1, 4, "comment is not closed"},
    {"UnclosedCData", "<a><![CDATA[ x", 1, 4, "CDATA section is not closed"},
    {"CDataOutsideRoot", "<![CDATA[x]]><a/>", 1, 1, "only allowed inside an element"},
    {"CDataEndInText", "<a>x ]]> y</a>", 1, 6, "']]>' is not allowed in text"},
    {"XmlDeclarationNotFirst", "<a/>\n<?xml version=\"1.0\"?>", 2, 1, "only allowed at the very start"},
    {"XmlDeclarationAfterWhitespace", " <?xml version=\"1.0\"?><a/>", 1, 2, "only allowed at the very start"},
    {"XmlDeclarationBadVersion", "<?xml version=\"2.0\"?><a/>", 1, 16, "unsupported XML version '2.0'"},
    {"XmlDeclarationBadEncoding", "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a/>", 1, 31, "unsupported encoding 'ISO-8859-1'"},
    {"XmlDeclarationNoVersion", "<?xml encoding=\"UTF-8\"?><a/>", 1, 7, "'encoding' must follow 'version'"},
    {"XmlDeclarationUnknownPseudo", "<?xml version=\"1.0\" foo=\"x\"?><a/>", 1, 21, "unknown pseudo-attribute 'foo'"},
    {"XmlDeclarationUnclosed", "<?xml version=\"1.0\"", 1, 1, "XML declaration is not closed"},
    {"UnclosedProcessingInstruction", "<a><?pi data</a>", 1, 4, "processing instruction <?pi is not closed"},
    {"Utf16ByteOrderMark", std::string("\xFF\xFE<\0a\0/\0>\0", 10), 1, 1, "UTF-16"},
    {"Utf16WithoutByteOrderMark", std::string("<\0?\0x\0m\0l\0", 10), 1, 1, "UTF-16"},
    // UTF-32 little-endian's mark FF FE 00 00 starts with UTF-16's: it is told apart.
    {"Utf32LittleEndian", std::string("\xFF\xFE\0\0<\0\0\0a\0\0\0", 12), 1, 1, "UTF-32"},
    {"Utf32BigEndian", std::string("\0\0\xFE\xFF\0\0\0<\0\0\0a", 12), 1, 1, "UTF-32"},
    {"Utf32WithoutByteOrderMark", std::string("<\0\0\0a\0\0\0", 8), 1, 1, "UTF-32"},
    {"InvalidUtf8StartByte", "<a>\n x\xFFy</a>", 2, 3, "byte 0xFF cannot start a character"},
    {"InvalidUtf8Continuation", "<a>\xC3(</a>", 1, 4, "not a continuation byte"},
    {"Utf8Overlong", "<a>\xC0\xAF</a>", 1, 4, "overlong"},
    {"Utf8Overlong3Byte", "<a>\xE0\x80\xAF</a>", 1, 4, "overlong encoding of U+002F"},
    {"Utf8Surrogate", "<a>\xED\xA0\x80</a>", 1, 4, "encoded surrogate U+D800"},
    {"Utf8AboveRange", "<a>\xF4\x90\x80\x80</a>", 1, 4, "above U+10FFFF"},
    {"Utf8Truncated", "<a/>\xE2\x82", 1, 5, "ends inside a multi-byte character"},
    {"Utf8LoneContinuation", "<a>\x80</a>", 1, 4, "unexpected continuation byte"},
    {"ControlCharacter", "<a>\x01</a>", 1, 4, "U+0001 (a control character) is not allowed"},
    {"NulByte", std::string("<a>\0</a>", 8), 1, 4, "U+0000"},
    {"NonCharacterFFFE", "<a>\xEF\xBF\xBE</a>", 1, 4, "U+FFFE is not allowed"},
    {"TooDeep", "<a><a><a><a><a><a><a><a><a/></a></a></a></a></a></a></a></a>", 1, 25, "nested more than 8 deep"},
    {"TooManyAttributes", "<a a=\"\" b=\"\" c=\"\" d=\"\" e=\"\"/>", 1, 24, "more than 4 attributes"},
    {"ReservedPiTargetInside", "<a><?XML x?></a>", 1, 4, "only allowed at the very start"},
    {"EndTagWithoutName", "<a></ >", 1, 6, "expected an element name after '</'"},
    {"LineColumnAfterMultibyte", "<a>\n\xC3\xA9\xC3\xA9 &bad;</a>", 2, 4, "unknown entity '&bad;'"},
};

INSTANTIATE_TEST_SUITE_P(Cases, XmlMalformed, ::testing::ValuesIn(kMalformed),
                         [](const ::testing::TestParamInfo<Malformed>& param) { return std::string(param.param.name); });

TEST(XmlParser, InputSizeLimit) {
  ParseOptions options;
  options.maxInputBytes = 16;
  SourceFile source("test.xml", "<a>0123456789012345</a>");
  try {
    parse(source, options);
    FAIL();
  } catch (const CompileError& e) {
    EXPECT_NE(e.diagnostic().message.find("above the limit of 16 bytes"), std::string::npos);
  }
}

TEST(XmlParser, TruncatedInputAtEveryPositionFailsCleanly) {
  // Every prefix of a valid document is either valid or reports an error inside the text:
  // never a crash and never a position past the end.
  const std::string text =
      "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\"><!-- c -->\n"
      "  <input name=\"a&amp;b\" value='1, 2'/><![CDATA[x]]><?p q?>&#x41;</materialx>\n";
  for (size_t n = 0; n < text.size(); ++n) {
    SourceFile source("prefix.xml", text.substr(0, n));
    try {
      parse(source);
    } catch (const CompileError& e) {
      EXPECT_LE(e.diagnostic().location.offset, n);
    }
  }
}

}  // namespace
}  // namespace mxc::xml
