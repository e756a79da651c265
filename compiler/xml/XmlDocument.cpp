#include "compiler/xml/XmlDocument.h"

#include <algorithm>
#include <cstring>

namespace mxc::xml {

std::string_view Element::name() const { return document_->node(index_).name; }

SourceLocation Element::location() const { return document_->locationOf(document_->node(index_).offset); }

std::span<const Attribute> Element::attributes() const {
  return document_->attributes(document_->node(index_));
}

const Attribute* Element::findAttribute(std::string_view name) const {
  for (const Attribute& a : attributes()) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

std::optional<std::string_view> Element::attribute(std::string_view name) const {
  if (const Attribute* a = findAttribute(name)) return a->value;
  return std::nullopt;
}

std::string_view Element::attributeOr(std::string_view name, std::string_view fallback) const {
  const Attribute* a = findAttribute(name);
  return a ? a->value : fallback;
}

std::vector<Element> Element::children() const {
  std::vector<Element> out;
  for (uint32_t i = document_->node(index_).firstChild; i != Node::kNone; i = document_->node(i).nextSibling) {
    if (document_->node(i).kind == NodeKind::Element) out.emplace_back(document_, i);
  }
  return out;
}

std::vector<uint32_t> Element::childNodes() const {
  std::vector<uint32_t> out;
  for (uint32_t i = document_->node(index_).firstChild; i != Node::kNone; i = document_->node(i).nextSibling) {
    out.push_back(i);
  }
  return out;
}

std::string Element::text() const {
  std::string out;
  for (uint32_t i = document_->node(index_).firstChild; i != Node::kNone; i = document_->node(i).nextSibling) {
    const Node& n = document_->node(i);
    if (n.kind == NodeKind::Text || n.kind == NodeKind::CData) out += n.value;
  }
  return out;
}

Element Element::parent() const {
  uint32_t p = document_->node(index_).parent;
  return p == Node::kNone ? Element() : Element(document_, p);
}

std::string_view Document::store(std::string_view text) {
  if (text.empty()) return {};
  if (chunks_.empty() || chunkUsed_ + text.size() > chunkSize_) {
    // Chunks of at least 64 KiB keep the number of allocations small; a longer string gets its own chunk.
    chunkSize_ = std::max<size_t>(size_t{64} << 10, text.size());
    chunks_.push_back(std::make_unique<char[]>(chunkSize_));
    chunkUsed_ = 0;
  }
  char* dest = chunks_.back().get() + chunkUsed_;
  std::memcpy(dest, text.data(), text.size());
  chunkUsed_ += text.size();
  return std::string_view(dest, text.size());
}

}  // namespace mxc::xml
