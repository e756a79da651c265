#pragma once
/// \file
/// The tree the XML parser produces: elements with attributes, text, CDATA, comments and
/// processing instructions, each with its byte offset in the source.
///
/// Storage is flat (one vector of nodes, one of attributes) and strings are views into the
/// source text unless they had to be decoded (entities, line-end normalisation), so a
/// document costs a few allocations whatever its size.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/common/SourceFile.h"

namespace mxc::xml {

enum class NodeKind : uint8_t { Element, Text, CData, Comment, ProcessingInstruction };

/// One attribute, after entity decoding and attribute-value normalisation (XML 1.0 §3.3.3).
struct Attribute {
  std::string_view name;
  std::string_view value;
  uint32_t nameOffset = 0;   ///< offset of the attribute name
  uint32_t valueOffset = 0;  ///< offset of the first character inside the quotes
  bool decoded = false;      ///< true when `value` differs from the raw source text
};

/// A node of the flat tree. Indices link nodes; `kNone` marks "no such node".
struct Node {
  static constexpr uint32_t kNone = UINT32_MAX;
  NodeKind kind = NodeKind::Element;
  std::string_view name;   ///< element name, or the target of a processing instruction
  std::string_view value;  ///< text, CDATA, comment or instruction content
  uint32_t offset = 0;     ///< offset of the '<' that starts the node (first character for text)
  uint32_t firstAttribute = 0;
  uint32_t attributeCount = 0;
  uint32_t parent = kNone;
  uint32_t firstChild = kNone;
  uint32_t lastChild = kNone;
  uint32_t nextSibling = kNone;
};

class Document;

/// A light handle on an element of a Document (the document must outlive it).
class Element {
 public:
  Element() = default;
  Element(const Document* document, uint32_t index) : document_(document), index_(index) {}

  bool valid() const { return document_ != nullptr; }
  std::string_view name() const;
  SourceLocation location() const;

  std::span<const Attribute> attributes() const;
  const Attribute* findAttribute(std::string_view name) const;
  /// The attribute's value, or nullopt when absent.
  std::optional<std::string_view> attribute(std::string_view name) const;
  /// The attribute's value, or `fallback` when absent.
  std::string_view attributeOr(std::string_view name, std::string_view fallback) const;

  /// Child elements in document order (text, comments and instructions are skipped).
  std::vector<Element> children() const;
  /// Every child node index, for callers that need text or comments too.
  std::vector<uint32_t> childNodes() const;
  /// Concatenated text and CDATA content of the direct children.
  std::string text() const;
  Element parent() const;

  const Document& document() const { return *document_; }
  uint32_t index() const { return index_; }

 private:
  const Document* document_ = nullptr;
  uint32_t index_ = Node::kNone;
};

/// A parsed XML document. Holds its nodes and attributes; strings point into the
/// SourceFile (which must outlive the document) or into the document's own storage.
class Document {
 public:
  explicit Document(const SourceFile& source) : source_(&source) {}
  Document(Document&&) = default;
  Document& operator=(Document&&) = default;

  const SourceFile& source() const { return *source_; }
  Element root() const { return Element(this, rootIndex_); }
  const Node& node(uint32_t index) const { return nodes_[index]; }
  size_t nodeCount() const { return nodes_.size(); }
  std::span<const Attribute> attributes(const Node& node) const {
    return std::span<const Attribute>(attributes_).subspan(node.firstAttribute, node.attributeCount);
  }
  SourceLocation locationOf(uint32_t offset) const { return SourceLocation{source_, offset}; }

 private:
  friend class Parser;

  const SourceFile* source_;
  std::vector<Node> nodes_;
  std::vector<Attribute> attributes_;
  /// Copies a decoded string into storage that lives as long as the document.
  std::string_view store(std::string_view text);

  std::vector<std::unique_ptr<char[]>> chunks_;  // arena for decoded strings
  size_t chunkUsed_ = 0;
  size_t chunkSize_ = 0;
  uint32_t rootIndex_ = Node::kNone;
};

}  // namespace mxc::xml
