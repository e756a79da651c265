#include "compiler/resolve/ResolvedGraph.h"

namespace mxc::resolve {

std::string_view ResolvedInput::structLiteral() const {
  if (structValue.empty()) return {};
  const doc::Port* from = source == InputSource::Value ? instance : declaration;
  return from && from->valueString ? *from->valueString : std::string_view();
}

std::string_view inputSourceName(InputSource source) {
  switch (source) {
    case InputSource::Value: return "value";
    case InputSource::Default: return "default";
    case InputSource::Connection: return "connection";
    case InputSource::Interface: return "interface";
    case InputSource::GeomProp: return "geomprop";
    case InputSource::Unset: return "unset";
  }
  return "unset";
}

const ResolvedInput* ResolvedNode::findInput(std::string_view n) const {
  for (const ResolvedInput& in : inputs) {
    if (in.name == n) return &in;
  }
  return nullptr;
}

const ResolvedNode* ResolvedGraph::findNode(std::string_view n) const {
  for (const auto& node : nodes) {
    if (node->name() == n) return node.get();
  }
  return nullptr;
}

const ResolvedInput* ResolvedGraph::findInterface(std::string_view n) const {
  for (const ResolvedInput& in : interface) {
    if (in.name == n) return &in;
  }
  return nullptr;
}

const ResolvedInput* ResolvedGraph::findOutput(std::string_view n) const {
  for (const ResolvedInput& out : outputs) {
    if (out.name == n) return &out;
  }
  return nullptr;
}

const ResolvedGraph* ResolvedDocument::findGraph(std::string_view n) const {
  for (const auto& g : graphs) {
    if (g->name() == n) return g.get();
  }
  return nullptr;
}

}  // namespace mxc::resolve
