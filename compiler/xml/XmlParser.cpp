#include "compiler/xml/XmlParser.h"

#include <cstring>
#include <string>
#include <unordered_set>

#include <fmt/format.h>

#include "compiler/xml/Utf8.h"

namespace mxc::xml {

/// One parse of one document. Works on the SourceFile's std::string, whose terminating NUL
/// is the end sentinel: checkXmlText has already refused NUL inside the text, so `*p == 0`
/// means "end of input" everywhere below and one-byte lookahead never leaves the buffer.
class Parser {
 public:
  Parser(const SourceFile& source, const ParseOptions& options)
      : options_(options),
        doc_(source),
        begin_(source.text().data()),
        end_(begin_ + source.text().size()),
        p_(begin_) {}

  Document run();

 private:
  [[noreturn]] void fail(const char* at, std::string message) const {
    throw CompileError(Diagnostic{Severity::Error, doc_.locationOf(offsetOf(at)), std::move(message)});
  }
  uint32_t offsetOf(const char* at) const { return static_cast<uint32_t>(at - begin_); }
  /// A raw '<' in an attribute value, kept (ParseOptions::warnings says why) with a warning.
  void keepRawLessThan(const char* at, std::string_view attributeName) const {
    options_.warnings->push_back(Diagnostic{
        Severity::Warning, doc_.locationOf(offsetOf(at)),
        fmt::format("'<' in the value of attribute '{}' is not well-formed XML (write '&lt;'); read as written, as "
                    "MaterialX reads it",
                    attributeName)});
  }
  std::string where(const char* at) const {
    LineColumn lc = doc_.source().lineColumn(offsetOf(at));
    return fmt::format("line {}, column {}", lc.line, lc.column);
  }
  bool startsWith(const char* at, std::string_view literal) const {
    return static_cast<size_t>(end_ - at) >= literal.size() && std::memcmp(at, literal.data(), literal.size()) == 0;
  }
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  bool skipSpace() {
    const char* start = p_;
    while (isSpace(*p_)) ++p_;
    return p_ != start;
  }
  /// A printable description of the character at `at` for messages.
  std::string describe(const char* at) const;

  void checkEncoding();
  void parseXmlDeclaration();
  void parseMisc(bool beforeRoot);
  void parseContent();
  /// Parses a start tag at '<'; returns true when the element stays open (not self-closing).
  bool parseStartTag(uint32_t parent, uint32_t& index);
  void parseEndTag(uint32_t open);
  void parseComment(uint32_t parent);
  void parseCData(uint32_t parent);
  void parseProcessingInstruction(uint32_t parent);
  void parseText(uint32_t parent);
  void refuseDeclaration(const char* at) const;
  std::string_view parseName(const char* what);
  std::string_view parseAttributeValue(std::string_view attributeName, bool& decoded);
  /// Decodes the reference at '&' into scratch_, moving p_ past its ';'.
  void decodeReference();
  uint32_t addNode(NodeKind kind, uint32_t parent, const char* at);

  ParseOptions options_;
  Document doc_;
  const char* begin_;
  const char* end_;
  const char* p_;
  std::vector<uint32_t> open_;  // indices of the elements whose end tag is pending
  std::string scratch_;        // decoding buffer, reused
};

std::string Parser::describe(const char* at) const {
  if (at >= end_) return "end of input";
  uint32_t c;
  decodeUtf8(at, c);
  if (c >= 0x21 && c < 0x7F) return fmt::format("'{}'", static_cast<char>(c));
  if (c == ' ') return "a space";
  if (c == '\n' || c == '\r') return "a line break";
  if (c == '\t') return "a tab";
  return codePointName(c);
}

uint32_t Parser::addNode(NodeKind kind, uint32_t parent, const char* at) {
  const auto index = static_cast<uint32_t>(doc_.nodes_.size());
  Node node;
  node.kind = kind;
  node.offset = offsetOf(at);
  node.parent = parent;
  doc_.nodes_.push_back(node);
  if (parent != Node::kNone) {
    Node& up = doc_.nodes_[parent];
    if (up.lastChild == Node::kNone) {
      up.firstChild = index;
    } else {
      doc_.nodes_[up.lastChild].nextSibling = index;
    }
    up.lastChild = index;
  }
  return index;
}

void Parser::checkEncoding() {
  const size_t size = static_cast<size_t>(end_ - begin_);
  if (size > options_.maxInputBytes) {
    fail(begin_, fmt::format("the input is {} bytes, above the limit of {} bytes", size, options_.maxInputBytes));
  }
  if (size == 0) fail(begin_, "the document is empty");
  const auto* u = reinterpret_cast<const unsigned char*>(begin_);
  // XML 1.0 Appendix F: the encoding shows in the first four bytes, with or without a
  // byte-order mark. UTF-32 is tested first: its little-endian mark FF FE 00 00 begins with
  // UTF-16's FF FE.
  auto starts = [&](std::initializer_list<unsigned char> bytes) {
    if (size < bytes.size()) return false;
    size_t i = 0;
    for (unsigned char b : bytes) {
      if (u[i++] != b) return false;
    }
    return true;
  };
  if (starts({0xFF, 0xFE, 0x00, 0x00}) || starts({0x00, 0x00, 0xFE, 0xFF}) || starts({0x3C, 0x00, 0x00, 0x00}) ||
      starts({0x00, 0x00, 0x00, 0x3C})) {
    fail(begin_, "the document is UTF-32 encoded; only UTF-8 is supported");
  }
  if (starts({0xFF, 0xFE}) || starts({0xFE, 0xFF}) || starts({0x3C, 0x00, 0x3F, 0x00}) || starts({0x00, 0x3C, 0x00, 0x3F})) {
    fail(begin_, "the document is UTF-16 encoded; only UTF-8 is supported");
  }
  if (auto error = checkXmlText(std::string_view(begin_, size))) fail(begin_ + error->offset, error->message);
  if (size >= 3 && u[0] == 0xEF && u[1] == 0xBB && u[2] == 0xBF) p_ += 3;  // UTF-8 byte-order mark
}

std::string_view Parser::parseName(const char* what) {
  const char* start = p_;
  uint32_t c;
  int length = decodeUtf8(p_, c);
  if (*p_ == 0 || !isNameStartChar(c)) {
    fail(p_, fmt::format("expected {}, found {}", what, describe(p_)));
  }
  p_ += length;
  for (;;) {
    const auto b = static_cast<unsigned char>(*p_);
    if (b < 0x80) {
      // ASCII NameChar: letters, digits, '_', ':', '-', '.'
      if ((b >= 'a' && b <= 'z') || (b >= 'A' && b <= 'Z') || (b >= '0' && b <= '9') || b == '_' || b == ':' ||
          b == '-' || b == '.') {
        ++p_;
        continue;
      }
      break;
    }
    length = decodeUtf8(p_, c);
    if (!isNameChar(c)) break;
    p_ += length;
  }
  return std::string_view(start, static_cast<size_t>(p_ - start));
}

void Parser::decodeReference() {
  const char* amp = p_;
  ++p_;
  if (*p_ == '#') {
    ++p_;
    const bool hex = *p_ == 'x';
    if (hex) ++p_;
    uint32_t value = 0;
    const char* digits = p_;
    for (;; ++p_) {
      const char c = *p_;
      uint32_t digit;
      if (c >= '0' && c <= '9') {
        digit = static_cast<uint32_t>(c - '0');
      } else if (hex && c >= 'a' && c <= 'f') {
        digit = static_cast<uint32_t>(c - 'a' + 10);
      } else if (hex && c >= 'A' && c <= 'F') {
        digit = static_cast<uint32_t>(c - 'A' + 10);
      } else {
        break;
      }
      value = value * (hex ? 16u : 10u) + digit;
      // Stop accumulating past the Unicode range so the value cannot overflow.
      if (value > 0x10FFFF) fail(amp, "character reference is above U+10FFFF, the largest Unicode code point");
    }
    if (p_ == digits) {
      fail(amp, hex ? "character reference '&#x' needs hexadecimal digits" : "character reference '&#' needs digits");
    }
    if (*p_ != ';') fail(p_, fmt::format("character reference is missing its ';' (found {})", describe(p_)));
    ++p_;
    if (!isXmlChar(value)) {
      fail(amp, fmt::format("character reference names {}, which XML does not allow", codePointName(value)));
    }
    appendUtf8(scratch_, value);
    return;
  }
  uint32_t c;
  decodeUtf8(p_, c);
  if (*p_ == 0 || !isNameStartChar(c)) fail(amp, "'&' must be written as '&amp;' (it starts an entity reference)");
  std::string_view name = parseName("an entity name");
  if (*p_ != ';') fail(amp, fmt::format("entity reference '&{}' is missing its ';'", name));
  ++p_;
  if (name == "lt") {
    scratch_ += '<';
  } else if (name == "gt") {
    scratch_ += '>';
  } else if (name == "amp") {
    scratch_ += '&';
  } else if (name == "apos") {
    scratch_ += '\'';
  } else if (name == "quot") {
    scratch_ += '"';
  } else {
    fail(amp, fmt::format("unknown entity '&{};': only &lt; &gt; &amp; &apos; &quot; and numeric character "
                          "references are allowed (DTDs are not supported)",
                          name));
  }
}

std::string_view Parser::parseAttributeValue(std::string_view attributeName, bool& decoded) {
  const char quote = *p_;
  const char* open = p_;
  ++p_;
  const char* start = p_;
  // Fast scan: most values have nothing to decode and stay a view into the source.
  for (;;) {
    while (*p_ != quote && *p_ != 0 && *p_ != '<' && *p_ != '&' && *p_ != '\t' && *p_ != '\n' && *p_ != '\r') ++p_;
    if (*p_ != '<' || !options_.warnings) break;
    keepRawLessThan(p_, attributeName);
    ++p_;
  }
  decoded = *p_ != quote && *p_ != 0 && *p_ != '<';
  if (!decoded) {
    if (*p_ == 0) {
      fail(open, fmt::format("the value of attribute '{}' is not closed: end of input before the closing {}",
                             attributeName, quote));
    }
    if (*p_ == '<') {
      fail(p_, fmt::format("'<' is not allowed in the value of attribute '{}'; write '&lt;'", attributeName));
    }
    std::string_view value(start, static_cast<size_t>(p_ - start));
    ++p_;
    return value;
  }
  scratch_.assign(start, static_cast<size_t>(p_ - start));
  for (;;) {
    const char c = *p_;
    if (c == quote) break;
    if (c == 0) {
      fail(open, fmt::format("the value of attribute '{}' is not closed: end of input before the closing {}",
                             attributeName, quote));
    }
    if (c == '<') {
      if (!options_.warnings) {
        fail(p_, fmt::format("'<' is not allowed in the value of attribute '{}'; write '&lt;'", attributeName));
      }
      keepRawLessThan(p_, attributeName);
    }
    if (c == '&') {
      decodeReference();
      continue;
    }
    // Attribute-value normalisation (XML 1.0 §3.3.3): each line break or tab becomes one space.
    if (c == '\r' && p_[1] == '\n') ++p_;
    scratch_ += (c == '\t' || c == '\n' || c == '\r') ? ' ' : c;
    ++p_;
  }
  ++p_;
  return doc_.store(scratch_);
}

void Parser::refuseDeclaration(const char* at) const {
  const char* name = at + 2;
  std::string_view keyword = "declaration";
  for (std::string_view k : {"DOCTYPE", "ENTITY", "ELEMENT", "ATTLIST", "NOTATION"}) {
    if (startsWith(name, k)) keyword = k;
  }
  if (keyword == "declaration") fail(at, "unexpected '<!': expected '<!--' (a comment) or '<![CDATA['");
  fail(at, fmt::format("<!{}> is not supported: mxc refuses DTDs and entity declarations (so no entity can be "
                       "expanded)",
                       keyword));
}

bool Parser::parseStartTag(uint32_t parent, uint32_t& index) {
  const char* open = p_;
  ++p_;  // '<'
  if (open_.size() >= options_.maxDepth) {
    fail(open, fmt::format("elements are nested more than {} deep", options_.maxDepth));
  }
  uint32_t c;
  decodeUtf8(p_, c);
  if (*p_ == 0 || !isNameStartChar(c)) {
    fail(open, fmt::format("stray '<': expected an element name, '/', '!--', '![CDATA[' or '?' after it, found {}",
                           describe(p_)));
  }
  std::string_view name = parseName("an element name");
  index = addNode(NodeKind::Element, parent, open);
  doc_.nodes_[index].name = name;
  const auto firstAttribute = static_cast<uint32_t>(doc_.attributes_.size());
  doc_.nodes_[index].firstAttribute = firstAttribute;
  std::unordered_set<std::string_view> seen;  // used only for elements with many attributes
  for (;;) {
    const bool spaced = skipSpace();
    if (*p_ == '>') {
      ++p_;
      return true;
    }
    if (*p_ == '/') {
      if (p_[1] != '>') fail(p_, fmt::format("expected '>' after '/' in the tag <{}>", name));
      p_ += 2;
      return false;
    }
    if (*p_ == 0) fail(open, fmt::format("the start tag <{}> is not closed: end of input before its '>'", name));
    if (*p_ == '<') fail(p_, fmt::format("the start tag <{}> is not closed: found '<' before its '>'", name));
    decodeUtf8(p_, c);
    if (!isNameStartChar(c)) fail(p_, fmt::format("unexpected {} in the start tag <{}>", describe(p_), name));
    if (!spaced) fail(p_, fmt::format("attributes of <{}> must be separated by whitespace", name));
    Attribute attribute;
    attribute.nameOffset = offsetOf(p_);
    attribute.name = parseName("an attribute name");
    skipSpace();
    if (*p_ != '=') {
      fail(p_, fmt::format("expected '=' after the attribute name '{}', found {}", attribute.name, describe(p_)));
    }
    ++p_;
    skipSpace();
    if (*p_ != '"' && *p_ != '\'') {
      fail(p_, fmt::format("the value of attribute '{}' must be in quotes, found {}", attribute.name, describe(p_)));
    }
    attribute.valueOffset = offsetOf(p_ + 1);
    attribute.value = parseAttributeValue(attribute.name, attribute.decoded);

    const auto count = static_cast<uint32_t>(doc_.attributes_.size()) - firstAttribute;
    if (count >= options_.maxAttributes) {
      fail(begin_ + attribute.nameOffset,
           fmt::format("<{}> has more than {} attributes", name, options_.maxAttributes));
    }
    // Duplicate check: a scan for small elements, a hash set beyond 16 attributes so that
    // an element with thousands of attributes still parses in linear time.
    bool duplicate = false;
    if (count < 16) {
      for (uint32_t i = firstAttribute; i < firstAttribute + count; ++i) {
        if (doc_.attributes_[i].name == attribute.name) duplicate = true;
      }
    } else {
      if (seen.empty()) {
        for (uint32_t i = firstAttribute; i < firstAttribute + count; ++i) seen.insert(doc_.attributes_[i].name);
      }
      duplicate = !seen.insert(attribute.name).second;
    }
    if (duplicate) {
      fail(begin_ + attribute.nameOffset,
           fmt::format("duplicate attribute '{}' on <{}>", attribute.name, name));
    }
    doc_.attributes_.push_back(attribute);
    doc_.nodes_[index].attributeCount = count + 1;
  }
}

void Parser::parseEndTag(uint32_t open) {
  const char* at = p_;
  p_ += 2;  // "</"
  std::string_view name = parseName("an element name after '</'");
  skipSpace();
  if (*p_ != '>') fail(p_, fmt::format("expected '>' to close the end tag </{}>, found {}", name, describe(p_)));
  ++p_;
  const Node& node = doc_.nodes_[open];
  if (name != node.name) {
    fail(at, fmt::format("mismatched end tag </{}>: the open element is <{}> (opened at {})", name, node.name,
                         where(begin_ + node.offset)));
  }
}

void Parser::parseComment(uint32_t parent) {
  const char* open = p_;
  p_ += 4;  // "<!--"
  const char* start = p_;
  for (;;) {
    const void* dash = std::memchr(p_, '-', static_cast<size_t>(end_ - p_));
    if (!dash) fail(open, "the comment is not closed: end of input before its '-->'");
    p_ = static_cast<const char*>(dash);
    if (p_[1] == '-') {
      if (p_[2] != '>') fail(p_, "'--' is not allowed inside a comment");
      break;
    }
    ++p_;
  }
  uint32_t index = addNode(NodeKind::Comment, parent, open);
  doc_.nodes_[index].value = std::string_view(start, static_cast<size_t>(p_ - start));
  p_ += 3;
}

void Parser::parseCData(uint32_t parent) {
  const char* open = p_;
  p_ += 9;  // "<![CDATA["
  const char* start = p_;
  for (;;) {
    const void* bracket = std::memchr(p_, ']', static_cast<size_t>(end_ - p_));
    if (!bracket) fail(open, "the CDATA section is not closed: end of input before its ']]>'");
    p_ = static_cast<const char*>(bracket);
    if (p_[1] == ']' && p_[2] == '>') break;
    ++p_;
  }
  std::string_view raw(start, static_cast<size_t>(p_ - start));
  uint32_t index = addNode(NodeKind::CData, parent, open);
  if (raw.find('\r') != std::string_view::npos) {
    scratch_.clear();
    for (size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '\r') {
        if (i + 1 < raw.size() && raw[i + 1] == '\n') continue;
        scratch_ += '\n';
      } else {
        scratch_ += raw[i];
      }
    }
    doc_.nodes_[index].value = doc_.store(scratch_);
  } else {
    doc_.nodes_[index].value = raw;
  }
  p_ += 3;
}

void Parser::parseProcessingInstruction(uint32_t parent) {
  const char* open = p_;
  p_ += 2;  // "<?"
  std::string_view target = parseName("a processing-instruction target after '<?'");
  if (target.size() == 3 && (target[0] | 0x20) == 'x' && (target[1] | 0x20) == 'm' && (target[2] | 0x20) == 'l') {
    fail(open, "the XML declaration '<?xml ...?>' is only allowed at the very start of the document");
  }
  if (!skipSpace() && !startsWith(p_, "?>")) {
    fail(p_, fmt::format("expected whitespace or '?>' after the processing-instruction target '{}'", target));
  }
  const char* start = p_;
  for (;;) {
    const void* q = std::memchr(p_, '?', static_cast<size_t>(end_ - p_));
    if (!q) fail(open, fmt::format("the processing instruction <?{} is not closed: end of input before its '?>'", target));
    p_ = static_cast<const char*>(q);
    if (p_[1] == '>') break;
    ++p_;
  }
  uint32_t index = addNode(NodeKind::ProcessingInstruction, parent, open);
  doc_.nodes_[index].name = target;
  doc_.nodes_[index].value = std::string_view(start, static_cast<size_t>(p_ - start));
  p_ += 2;
}

void Parser::parseXmlDeclaration() {
  const char* open = p_;
  p_ += 5;  // "<?xml"
  bool sawVersion = false;
  for (;;) {
    const bool spaced = skipSpace();
    if (startsWith(p_, "?>")) {
      p_ += 2;
      break;
    }
    if (*p_ == 0) fail(open, "the XML declaration is not closed: end of input before its '?>'");
    if (!spaced) fail(p_, fmt::format("expected whitespace or '?>' in the XML declaration, found {}", describe(p_)));
    const char* nameAt = p_;
    std::string_view name = parseName("a pseudo-attribute (version, encoding or standalone) in the XML declaration");
    skipSpace();
    if (*p_ != '=') fail(p_, fmt::format("expected '=' after '{}' in the XML declaration", name));
    ++p_;
    skipSpace();
    if (*p_ != '"' && *p_ != '\'') fail(p_, fmt::format("the value of '{}' must be in quotes", name));
    const char quote = *p_++;
    const char* valueAt = p_;
    while (*p_ != quote && *p_ != 0 && *p_ != '<' && *p_ != '>') ++p_;
    if (*p_ != quote) fail(valueAt - 1, fmt::format("the value of '{}' in the XML declaration is not closed", name));
    std::string_view value(valueAt, static_cast<size_t>(p_ - valueAt));
    ++p_;
    if (name == "version") {
      if (sawVersion) fail(nameAt, "duplicate 'version' in the XML declaration");
      if (value.size() < 3 || value.substr(0, 2) != "1." ||
          value.substr(2).find_first_not_of("0123456789") != std::string_view::npos) {
        fail(valueAt, fmt::format("unsupported XML version '{}': expected 1.0", value));
      }
      sawVersion = true;
    } else if (name == "encoding") {
      if (!sawVersion) fail(nameAt, "'encoding' must follow 'version' in the XML declaration");
      std::string lower;
      for (char c : value) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c + 32 : c);
      if (lower != "utf-8" && lower != "utf8" && lower != "us-ascii" && lower != "ascii") {
        fail(valueAt, fmt::format("unsupported encoding '{}': only UTF-8 is supported", value));
      }
    } else if (name == "standalone") {
      if (!sawVersion) fail(nameAt, "'standalone' must follow 'version' in the XML declaration");
      if (value != "yes" && value != "no") fail(valueAt, "'standalone' must be \"yes\" or \"no\"");
    } else {
      fail(nameAt, fmt::format("unknown pseudo-attribute '{}' in the XML declaration (expected version, encoding or "
                               "standalone)",
                               name));
    }
  }
  if (!sawVersion) fail(open, "the XML declaration needs a version, as in <?xml version=\"1.0\"?>");
}

void Parser::parseMisc(bool beforeRoot) {
  for (;;) {
    skipSpace();
    if (*p_ == 0) return;
    if (*p_ != '<') {
      fail(p_, beforeRoot ? "text before the root element: a document must start with '<'"
                          : "text after the root element: a document has exactly one root element");
    }
    if (startsWith(p_, "<!--")) {
      parseComment(Node::kNone);
    } else if (p_[1] == '?') {
      parseProcessingInstruction(Node::kNone);
    } else if (p_[1] == '!') {
      if (startsWith(p_, "<![CDATA[")) fail(p_, "a CDATA section is only allowed inside an element");
      refuseDeclaration(p_);
    } else if (beforeRoot) {
      return;  // the root element starts here
    } else {
      const Node& root = doc_.nodes_[doc_.rootIndex_];
      fail(p_, fmt::format("a document has exactly one root element, but more markup follows </{}>", root.name));
    }
  }
}

void Parser::parseText(uint32_t parent) {
  const char* start = p_;
  const void* lt = std::memchr(p_, '<', static_cast<size_t>(end_ - p_));
  const char* stop = lt ? static_cast<const char*>(lt) : end_;
  std::string_view raw(start, static_cast<size_t>(stop - start));
  // "]]>" may not appear in text (XML 1.0 §2.4).
  if (size_t k = raw.find("]]>"); k != std::string_view::npos) fail(start + k, "']]>' is not allowed in text");
  const bool plain = raw.find_first_of("&\r") == std::string_view::npos;
  if (plain) {
    p_ = stop;
    if (raw.find_first_not_of(" \t\n\r") == std::string_view::npos) return;  // whitespace between elements
    uint32_t index = addNode(NodeKind::Text, parent, start);
    doc_.nodes_[index].value = raw;
    return;
  }
  scratch_.clear();
  while (p_ < stop) {
    const char c = *p_;
    if (c == '&') {
      decodeReference();
      continue;
    }
    if (c == '\r') {
      if (p_[1] == '\n') ++p_;
      scratch_ += '\n';
      ++p_;
      continue;
    }
    scratch_ += c;
    ++p_;
  }
  if (scratch_.find_first_not_of(" \t\n") == std::string::npos) return;
  uint32_t index = addNode(NodeKind::Text, parent, start);
  doc_.nodes_[index].value = doc_.store(scratch_);
}

void Parser::parseContent() {
  uint32_t root;
  if (parseStartTag(Node::kNone, root)) open_.push_back(root);
  doc_.rootIndex_ = root;
  while (!open_.empty()) {
    const uint32_t parent = open_.back();
    if (*p_ == 0) {
      const Node& node = doc_.nodes_[parent];
      fail(p_, fmt::format("unexpected end of input: <{}> (opened at {}) is not closed", node.name,
                           where(begin_ + node.offset)));
    }
    if (*p_ != '<') {
      parseText(parent);
      continue;
    }
    switch (p_[1]) {
      case '/':
        parseEndTag(parent);
        open_.pop_back();
        break;
      case '!':
        if (startsWith(p_, "<!--")) {
          parseComment(parent);
        } else if (startsWith(p_, "<![CDATA[")) {
          parseCData(parent);
        } else {
          refuseDeclaration(p_);
        }
        break;
      case '?':
        parseProcessingInstruction(parent);
        break;
      default: {
        uint32_t child;
        if (parseStartTag(parent, child)) open_.push_back(child);
      }
    }
  }
}

Document Parser::run() {
  checkEncoding();
  if (startsWith(p_, "<?xml") && (isSpace(p_[5]) || p_[5] == '?')) parseXmlDeclaration();
  parseMisc(true);
  if (*p_ == 0) fail(p_, "the document has no root element");
  parseContent();
  parseMisc(false);
  return std::move(doc_);
}

Document parse(const SourceFile& source, const ParseOptions& options) {
  ParseOptions checked = options;
  // Offsets are 32-bit; never accept more than they can address.
  if (checked.maxInputBytes > 0xFFFFFFF0u) checked.maxInputBytes = 0xFFFFFFF0u;
  return Parser(source, checked).run();
}

}  // namespace mxc::xml
