#include <fmt/format.h>

#include "compiler/inspect/Inspect.h"

namespace mxc::inspect {

using resolve::InputSource;
using resolve::ResolvedGraph;
using resolve::ResolvedInput;
using resolve::ResolvedNode;

namespace {

/// DOT string literal: quotes and backslashes escaped.
std::string quote(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// A two-line DOT label: each line quoted as `quote` does, joined by DOT's own line break (the
/// escape \n, which quoting the joined text would turn into a literal backslash and n).
std::string twoLines(std::string_view first, std::string_view second) {
  const std::string a = quote(first);
  const std::string b = quote(second);
  return a.substr(0, a.size() - 1) + "\\n" + b.substr(1);
}

std::string graphOutputId(const ResolvedGraph& g, std::string_view output) {
  return fmt::format("{}/output:{}", g.name(), output);
}

std::string interfaceId(const ResolvedGraph& g, std::string_view name) {
  return fmt::format("{}/interface:{}", g.name(), name);
}

/// The DOT node an input's value comes from, or "" when it is not a connection.
std::string sourceId(const ResolvedInput& in, const ResolvedGraph* scope) {
  if (in.source == InputSource::Connection) {
    if (in.upstream.node) return nodeId(*in.upstream.node);
    if (in.upstream.graph) return graphOutputId(*in.upstream.graph, in.upstream.output);
  }
  if (in.source == InputSource::Interface && scope) return interfaceId(*scope, in.interfaceName);
  return {};
}

void edges(std::string& out, const ResolvedInput& in, const ResolvedGraph* scope, const std::string& target) {
  std::string from = sourceId(in, scope);
  if (from.empty()) return;
  out += fmt::format("  {} -> {} [label={}];\n", quote(from), quote(target), quote(in.name));
}

}  // namespace

std::string inspectDot(const InspectInput& input) {
  const resolve::ResolvedDocument& rd = input.document;
  std::string out = fmt::format("digraph {} {{\n  rankdir=LR;\n  node [shape=box, fontname=\"Helvetica\"];\n",
                                quote(rd.document->path()));
  auto nodeLine = [&](const ResolvedNode& n, const char* indent) {
    std::string shape = n.signature && n.signature->outputType() == "material" ? ", shape=doubleoctagon" : "";
    out += fmt::format("{}{} [label={}{}];\n", indent, quote(nodeId(n)),
                       twoLines(n.name(), fmt::format("<{}>", n.category())), shape);
  };
  for (const auto& n : rd.top.nodes) nodeLine(*n, "  ");
  for (const auto& g : rd.graphs) {
    out += fmt::format("  subgraph {} {{\n    label={};\n", quote("cluster_" + std::string(g->name())), quote(g->name()));
    for (const ResolvedInput& in : g->interface) {
      out += fmt::format("    {} [label={}, shape=ellipse];\n", quote(interfaceId(*g, in.name)), quote(in.name));
    }
    for (const ResolvedInput& o : g->outputs) {
      out += fmt::format("    {} [label={}, shape=ellipse];\n", quote(graphOutputId(*g, o.name)), quote(o.name));
    }
    for (const auto& n : g->nodes) nodeLine(*n, "    ");
    out += "  }\n";
  }
  for (const auto& n : rd.top.nodes) {
    for (const ResolvedInput& in : n->inputs) edges(out, in, nullptr, nodeId(*n));
  }
  for (const auto& g : rd.graphs) {
    for (const ResolvedInput& in : g->interface) edges(out, in, nullptr, interfaceId(*g, in.name));
    for (const ResolvedInput& o : g->outputs) edges(out, o, g.get(), graphOutputId(*g, o.name));
    for (const auto& n : g->nodes) {
      for (const ResolvedInput& in : n->inputs) edges(out, in, g.get(), nodeId(*n));
    }
  }
  out += "}\n";
  return out;
}

}  // namespace mxc::inspect
