#include "compiler/document/Document.h"

#include <charconv>

namespace mxc::doc {

namespace {

template <typename T>
const T* findByName(const std::vector<T>& items, std::string_view name) {
  for (const T& item : items) {
    if (item.name == name) return &item;
  }
  return nullptr;
}

SourceLocation attributeLocationOf(const xml::Element& element, SourceLocation fallback, std::string_view attribute) {
  if (element.valid()) {
    if (const xml::Attribute* a = element.findAttribute(attribute)) return element.document().locationOf(a->valueOffset);
  }
  return fallback;
}

}  // namespace

SourceLocation Port::attributeLocation(std::string_view attribute) const {
  return attributeLocationOf(element, location, attribute);
}

SourceLocation Node::attributeLocation(std::string_view attribute) const {
  return attributeLocationOf(element, location, attribute);
}

const Input* Node::findInput(std::string_view n) const { return findByName(inputs, n); }
Input* Node::findInput(std::string_view n) { return const_cast<Input*>(findByName(inputs, n)); }
const Input* NodeDef::findInput(std::string_view n) const { return findByName(inputs, n); }
const Output* NodeDef::findOutput(std::string_view n) const { return findByName(outputs, n); }
const Node* NodeGraph::findNode(std::string_view n) const { return findByName(nodes, n); }
Node* NodeGraph::findNode(std::string_view n) { return const_cast<Node*>(findByName(nodes, n)); }
const Input* NodeGraph::findInput(std::string_view n) const { return findByName(inputs, n); }
const Output* NodeGraph::findOutput(std::string_view n) const { return findByName(outputs, n); }

std::optional<Version> parseVersion(std::string_view text) {
  Version v;
  const char* p = text.data();
  const char* end = p + text.size();
  auto number = [&](int& out) {
    const auto [next, error] = std::from_chars(p, end, out);
    if (error != std::errc() || out < 0) return false;
    p = next;
    return true;
  };
  if (!number(v.major) || p == end || *p != '.') return std::nullopt;
  ++p;
  if (!number(v.minor)) return std::nullopt;
  int patch = 0;
  if (p != end && *p == '.') {
    ++p;
    if (!number(patch)) return std::nullopt;
  }
  if (p != end) return std::nullopt;
  return v;
}

Document::Document(xml::Document xml) : xml_(std::move(xml)) {}

Version Document::versionNumber() const { return parseVersion(version).value_or(Version{1, 39}); }

const Node* Document::findNode(std::string_view n) const { return findByName(nodes, n); }
const NodeGraph* Document::findNodeGraph(std::string_view n) const { return findByName(nodegraphs, n); }
const NodeDef* Document::findNodeDef(std::string_view n) const { return findByName(nodedefs, n); }

std::string_view Document::own(std::string text) {
  owned_.push_back(std::move(text));
  return owned_.back();
}

void Document::link() {
  for (NodeDef& nd : nodedefs) nd.document = this;
  for (Node& n : nodes) {
    n.document = this;
    n.graph = nullptr;
  }
  for (NodeGraph& g : nodegraphs) {
    g.document = this;
    for (Node& n : g.nodes) {
      n.document = this;
      n.graph = &g;
    }
  }
}

}  // namespace mxc::doc
