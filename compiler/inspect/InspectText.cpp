#include <deque>
#include <set>

#include <fmt/format.h>

#include "compiler/inspect/Inspect.h"

namespace mxc::inspect {

using resolve::InputSource;
using resolve::ResolvedGraph;
using resolve::ResolvedInput;
using resolve::ResolvedNode;

std::string nodeId(const ResolvedNode& node) {
  if (node.scope && node.scope->graph) return fmt::format("{}/{}", node.scope->graph->name, node.name());
  return std::string(node.name());
}

namespace {

std::string valueText(const doc::Value& value) {
  switch (value.type()) {
    case doc::ValueType::String:
    case doc::ValueType::Filename:
    case doc::ValueType::GeomName: return fmt::format("\"{}\"", value.str());
    default: return value.str();
  }
}

class TextReport {
 public:
  explicit TextReport(const InspectInput& input) : in_(input), doc_(*input.document.document) {}

  std::string run();

 private:
  /// "line 12" in the inspected file, "path:12" elsewhere (library or included file).
  std::string where(SourceLocation location) const {
    if (!location.valid()) return "";
    if (location.file == &doc_.source()) return fmt::format("line {}", location.line());
    return fmt::format("{}:{}", location.file->path(), location.line());
  }
  void line(int indent, const std::string& text) { out_ += std::string(static_cast<size_t>(indent), ' ') + text + "\n"; }
  void node(const ResolvedNode& n, int indent);
  /// One input line (`label` defaults to the input's name), then the tree behind a connection.
  void input(const ResolvedInput& in, const ResolvedGraph* scope, int indent, size_t width, std::string label = {});
  void graphOutput(const ResolvedGraph& graph, const ResolvedInput& out, int indent);
  void graph(const ResolvedGraph& g);
  /// Prints the trees deferred by `node` for their depth, each at the margin.
  void continueDeferred();

  /// Deeper than this, a node's tree continues in its own section at the left margin: a chain of
  /// n nodes indented by its depth would print O(n^2) spaces (a 10,000-node chain: 600 MB).
  static constexpr int kMaxIndent = 48;

  const InspectInput& in_;
  const doc::Document& doc_;
  std::string out_;
  std::deque<const ResolvedNode*> deferred_;  ///< nodes whose tree continues below
  std::set<const ResolvedNode*> shownNodes_;
  std::set<const ResolvedInput*> shownOutputs_;
};

void TextReport::node(const ResolvedNode& n, int indent) {
  std::string header = fmt::format("{} <{}>", nodeId(n), n.category());
  if (n.nodedef) {
    header += " " + std::string(n.nodedef->name);
    if (!n.nodedef->version.empty()) header += " v" + std::string(n.nodedef->version);
  } else {
    header += " (unresolved)";
  }
  if (shownNodes_.count(&n)) {
    line(indent, header + "  (shown above)");
    return;
  }
  if (indent > kMaxIndent) {
    line(indent, header + "  (continued below)");
    deferred_.push_back(&n);
    return;
  }
  shownNodes_.insert(&n);
  line(indent, fmt::format("{}  {}", header, where(n.node->location)));
  size_t width = 0;
  for (const ResolvedInput& i : n.inputs) width = std::max(width, i.name.size());
  for (const ResolvedInput& i : n.inputs) input(i, n.scope, indent + 2, std::min<size_t>(width, 40));
}

void TextReport::input(const ResolvedInput& i, const ResolvedGraph* scope, int indent, size_t width,
                       std::string label) {
  if (label.empty()) label = std::string(i.name);
  std::string text;
  switch (i.source) {
    case InputSource::Value: text = "= " + (i.value ? valueText(*i.value) : std::string(i.structLiteral())); break;
    case InputSource::Default:
      text = "= " + (i.value ? valueText(*i.value) : std::string(i.structLiteral())) + " (default)";
      break;
    case InputSource::GeomProp: text = fmt::format("geomprop {} (default)", i.geomprop); break;
    case InputSource::Unset: text = "(unset)"; break;
    case InputSource::Interface: {
      text = fmt::format("<- interface {}", i.interfaceName);
      if (scope) {
        if (const ResolvedInput* iface = scope->findInterface(i.interfaceName)) {
          if (iface->value) text += " = " + valueText(*iface->value);
          else if (iface->source == InputSource::GeomProp) text += fmt::format(" = geomprop {}", iface->geomprop);
        }
      }
      break;
    }
    case InputSource::Connection: {
      if (i.upstream.node) {
        text = fmt::format("<- {}", i.upstream.node->name());
        if (i.upstream.node->signature && i.upstream.node->signature->outputs.size() > 1) text += "." + std::string(i.upstream.output);
      } else if (i.upstream.graph) {
        text = fmt::format("<- {}.{}", i.upstream.graph->name(), i.upstream.output);
      }
      if (!i.channels.empty()) text += fmt::format(" channels \"{}\"", i.channels);
      break;
    }
  }
  // An input the node sets is located at its own element; a default at the nodedef.
  std::string location = where(i.location);
  if ((i.source == InputSource::Default || i.source == InputSource::GeomProp) && !location.empty()) {
    location = "nodedef " + location;
  }
  line(indent, fmt::format("{:<{}}  {:<9} {}{}", label, width, i.type, text, location.empty() ? "" : "  " + location));
  if (i.source != InputSource::Connection) return;
  if (i.upstream.node) {
    node(*i.upstream.node, indent + 2);
  } else if (i.upstream.graph) {
    if (const ResolvedInput* out = i.upstream.graph->findOutput(i.upstream.output)) graphOutput(*i.upstream.graph, *out, indent + 2);
  }
}

void TextReport::graphOutput(const ResolvedGraph& g, const ResolvedInput& out, int indent) {
  if (shownOutputs_.count(&out)) {
    line(indent, fmt::format("output {}.{}  (shown above)", g.name(), out.name));
    return;
  }
  shownOutputs_.insert(&out);
  std::string label = fmt::format("output {}.{}", g.name(), out.name);
  input(out, &g, indent, label.size(), label);
}

void TextReport::continueDeferred() {
  // Each deep tree continues once at the margin; a node reached again says "shown above".
  while (!deferred_.empty()) {
    const ResolvedNode* n = deferred_.front();
    deferred_.pop_front();
    if (shownNodes_.count(n)) continue;
    line(0, fmt::format("continued: {}", nodeId(*n)));
    node(*n, 2);
    line(0, "");
  }
}

void TextReport::graph(const ResolvedGraph& g) {
  std::string header = fmt::format("nodegraph {}", g.name());
  if (g.implements) header += fmt::format(" (implements {})", g.implements->name);
  line(0, fmt::format("{}  {}", header, where(g.graph->location)));
  if (!g.implements && !g.interface.empty()) {
    size_t width = 0;
    for (const ResolvedInput& i : g.interface) width = std::max(width, i.name.size());
    line(2, "interface:");
    for (const ResolvedInput& i : g.interface) input(i, nullptr, 4, std::min<size_t>(width, 32));
  }
  for (const ResolvedInput& out : g.outputs) graphOutput(g, out, 2);
  for (const auto& n : g.nodes) {
    if (!shownNodes_.count(n.get())) node(*n, 2);
  }
}

std::string TextReport::run() {
  const resolve::ResolvedDocument& rd = in_.document;
  line(0, fmt::format("document   {}", doc_.path()));
  std::string version = doc_.version.empty() ? "(none)" : std::string(doc_.version);
  line(0, fmt::format("materialx  {}{}", version, doc_.colorspace.empty() ? "" : fmt::format(", colorspace {}", doc_.colorspace)));
  for (const std::string& note : doc_.upgradeNotes) line(0, fmt::format("upgraded   {}", note));
  std::vector<std::string> libraries;
  for (const LibraryInfo& l : in_.libraries) libraries.push_back(fmt::format("{} ({} nodedefs)", l.name, l.nodedefs));
  line(0, fmt::format("libraries  {}", fmt::join(libraries, ", ")));
  for (const doc::Include& include : doc_.includes) {
    line(0, fmt::format("includes   {}{}", include.href, include.document ? "" : " (not loaded)"));
  }
  size_t nodedefs = 0;
  for (const doc::Document* d : rd.documents) nodedefs += d->nodedefs.size();
  if (nodedefs) line(0, fmt::format("defines    {} nodedef{}", nodedefs, nodedefs == 1 ? "" : "s"));
  line(0, "");

  if (rd.materials.empty()) line(0, "materials  (none)");
  for (const resolve::ResolvedMaterial& m : rd.materials) {
    line(0, fmt::format("material {} <{}>  {}", m.node->name(), m.node->category(), where(m.node->node->location)));
    shownNodes_.insert(m.node);
    size_t width = 0;
    for (const ResolvedInput& i : m.node->inputs) width = std::max(width, i.name.size());
    for (const ResolvedInput& i : m.node->inputs) input(i, nullptr, 2, width);
    line(0, "");
  }
  for (const auto& g : rd.graphs) {
    bool complete = true;
    for (const ResolvedInput& out : g->outputs) complete = complete && shownOutputs_.count(&out);
    if (complete && !g->outputs.empty()) continue;
    graph(*g);
    line(0, "");
  }
  continueDeferred();
  bool header = false;
  // Document-level nodes no material or graph reached, consumers last (reverse dependency order).
  for (auto it = rd.top.nodes.rbegin(); it != rd.top.nodes.rend(); ++it) {
    if (shownNodes_.count(it->get())) continue;
    if (!header) line(0, "other nodes:"), header = true;
    node(**it, 2);
  }
  continueDeferred();
  for (const doc::Document* d : rd.documents) {
    for (const doc::Look& look : d->looks) {
      line(0, fmt::format("look {}  {}", look.name, where(look.location)));
      for (const doc::MaterialAssign& a : look.assigns) {
        line(2, fmt::format("materialassign {}: material {} -> geom \"{}\"{}", a.name, a.material, a.geom,
                            a.collection.empty() ? "" : fmt::format(" collection {}", a.collection)));
      }
    }
  }
  size_t errors = in_.diagnostics.errorCount();
  size_t warnings = in_.diagnostics.omittedWarnings();
  for (const Diagnostic& d : in_.diagnostics.all()) warnings += d.severity == Severity::Warning;
  line(0, fmt::format("{} error{}, {} warning{}", errors, errors == 1 ? "" : "s", warnings, warnings == 1 ? "" : "s"));
  return out_;
}

}  // namespace

std::string inspectText(const InspectInput& input) { return TextReport(input).run(); }

}  // namespace mxc::inspect
