#pragma once
/// \file
/// What the version upgrades share: the nodes of one scope (the document level or one node
/// graph) with name lookup, fresh names and the ports that can name a node, and the nodes an
/// upgrade adds to a scope.

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/document/Document.h"

namespace mxc::doc {

/// The nodes of one scope (the document level or one graph) with name lookup.
struct ScopeNodes {
  std::vector<Node>* nodes;
  std::vector<Output>* outputs;  // the graph's outputs, or the document's own

  Node* find(std::string_view name) {
    for (Node& n : *nodes) {
      if (n.name == name) return &n;
    }
    return nullptr;
  }
  std::string uniqueName(const std::string& base) {
    std::string name = base;
    for (int i = 2; find(name); ++i) name = base + std::to_string(i);
    return name;
  }
  /// Every port in the scope that can name a node: node inputs and graph outputs.
  template <typename F>
  void forEachPort(F f) {
    for (Node& n : *nodes) {
      for (Input& in : n.inputs) f(in);
    }
    if (outputs) {
      for (Output& out : *outputs) f(out);
    }
  }
};

/// The document level, then each node graph.
inline std::vector<ScopeNodes> scopesOf(Document& doc) {
  std::vector<ScopeNodes> scopes{{&doc.nodes, &doc.outputs}};
  for (NodeGraph& g : doc.nodegraphs) scopes.push_back({&g.nodes, &g.outputs});
  return scopes;
}

/// The nodes an upgrade adds to a scope, appended to it once the scope's nodes are no longer
/// walked. Nodes are named by the index `add` returns: a reference would not survive the next.
struct AddedNodes {
  Document& doc;
  ScopeNodes scope;
  std::vector<Node> nodes;

  /// A node of `category` and `type` at `where`, named from `base` uniquely in the scope and
  /// among the nodes added so far.
  size_t add(std::string_view category, std::string_view type, const std::string& base, SourceLocation where) {
    std::string name = scope.uniqueName(base);
    for (int i = 2; std::any_of(nodes.begin(), nodes.end(), [&](const Node& a) { return a.name == name; }); ++i) {
      name = scope.uniqueName(base + "_" + std::to_string(i));
    }
    Node node;
    node.category = category;
    node.type = type;
    node.location = where;
    node.name = doc.own(name);
    nodes.push_back(std::move(node));
    return nodes.size() - 1;
  }
  /// A node at `near`'s place.
  size_t add(std::string_view category, std::string_view type, const std::string& base, const Node& near) {
    return add(category, type, base, near.location);
  }
  /// The input `name` of type `type` connected to added node `k`.
  Input connection(std::string_view name, std::string_view type, size_t k) const {
    Input in;
    in.name = name;
    in.type = type;
    in.nodename = nodes[k].name;
    in.location = nodes[k].location;
    return in;
  }
  /// `from` as the input `name` (its binding kept: a value, a connection or an interface
  /// name), or a value input of `type` written `fallback` when `from` is absent.
  Input moved(const Input* from, std::string_view name, std::string_view type, std::string_view fallback,
              SourceLocation where) {
    Input in;
    if (from) in = *from;
    in.name = name;
    in.type = type;
    in.element = {};
    if (!from) {
      in.location = where;
      in.valueLocation = where;
      in.valueString = doc.own(std::string(fallback));
      in.value = tryParseValue(valueTypeOf(type), *in.valueString);
    }
    return in;
  }
  void commit() {
    for (Node& n : nodes) scope.nodes->push_back(std::move(n));
    nodes.clear();
  }
};

}  // namespace mxc::doc
