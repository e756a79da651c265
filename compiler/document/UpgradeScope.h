#pragma once
/// \file
/// What the version upgrades share: the nodes of one scope (the document level or one node
/// graph) with name lookup, fresh names and the ports that can name a node.

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

}  // namespace mxc::doc
