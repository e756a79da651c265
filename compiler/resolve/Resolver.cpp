#include "compiler/resolve/Resolver.h"

#include <algorithm>
#include <set>
#include <unordered_map>

#include <fmt/format.h>

#include "compiler/resolve/Channels.h"
#include "compiler/resolve/NodeDefMatcher.h"

namespace mxc::resolve {

namespace {

/// A scope being resolved: its result and its nodes by name.
struct Scope {
  ResolvedGraph* resolved = nullptr;
  const doc::NodeGraph* graph = nullptr;  // null at document level
  std::unordered_map<std::string_view, ResolvedNode*> nodes;
  // The scope's interface inputs, outputs and tokens: its graph's, or at document level those
  // written directly under <materialx> (the document and its includes).
  std::vector<const doc::Input*> inputs;
  std::vector<const doc::Output*> outputs;
  std::vector<const doc::Token*> tokens;

  std::string describe() const {
    return graph ? fmt::format("node graph '{}'", graph->name) : std::string("the document");
  }
};

/// What a document (with its includes) has at its top level.
struct TopLevel {
  std::vector<const doc::Node*> nodes;
  std::vector<const doc::Input*> inputs;
  std::vector<const doc::Output*> outputs;
  std::vector<const doc::Token*> tokens;
};

/// An input as a nodedef declares it, not yet given a source.
ResolvedInput declaredInput(const doc::Input& declaration) {
  ResolvedInput input;
  input.name = declaration.name;
  input.type = declaration.type;
  input.declaration = &declaration;
  input.location = declaration.location;
  return input;
}

/// The nodedef's fallback for an input nothing sets: its default value, else its default
/// geometric property; otherwise the input stays unset.
void applyDefault(ResolvedInput& input, const doc::Input& declaration) {
  if (declaration.value && declaration.value->type() != doc::ValueType::None) {
    input.source = InputSource::Default;
    input.value = declaration.value;
  } else if (!declaration.defaultgeomprop.empty()) {
    input.source = InputSource::GeomProp;
    input.geomprop = declaration.defaultgeomprop;
  }
}

/// A dependency edge found while ordering: the node depended on and the input that makes it.
struct Dependency {
  ResolvedNode* node;
  const ResolvedInput* input;
};

class Resolver {
 public:
  Resolver(const lib::NodeLibrary& library, Diagnostics& diagnostics) : library_(library), diagnostics_(diagnostics) {}

  /// Resolves the given document-level nodes and graphs as one document.
  void resolve(ResolvedGraph& top, const TopLevel& topLevel, std::vector<std::unique_ptr<ResolvedGraph>>& graphs,
               const std::vector<const doc::NodeGraph*>& docGraphs);

 private:
  void createNodes(Scope& scope, const std::vector<const doc::Node*>& nodes);
  void resolveNode(Scope& scope, ResolvedNode& node);
  void resolveInterface(Scope& scope);
  void resolveOutputs(Scope& scope);
  /// Resolves what a port is set to (connection, interface, value), checked against `type`.
  /// A filename value's [token]s are those tokensSeen(tokenScope, ownTokens) gives: the node's
  /// own, then those of `tokenScope` (null: `scope`), then the document's.
  /// Reads the struct literal a port of a struct type gives into result.structValue; false
  /// (after reporting a bad literal once) when it gives none or the type is not a struct.
  bool readStruct(const doc::Port& port, ResolvedInput& result);
  void resolvePort(const Scope& scope, const doc::Port& port, ResolvedInput& result,
                   const std::vector<doc::Token>* ownTokens = nullptr, const Scope* tokenScope = nullptr);
  /// The tokens a port of `scope` sees, innermost first: `own` (a node's), the scope's, and the
  /// document's (MaterialX 1.39 "Filename Substitutions": the nearest enclosing token wins).
  std::vector<const doc::Token*> tokensSeen(const Scope& scope, const std::vector<doc::Token>* own) const;
  void checkConnectionType(const doc::Port& port, ResolvedInput& result);
  void checkEnum(const ResolvedInput& input);
  void order(std::vector<Scope*>& scopes);
  std::vector<Dependency> dependencies(ResolvedNode& node);
  void followInto(const ResolvedInput& input, const ResolvedInput& via, std::vector<Dependency>& out, int depth);

  const lib::NodeLibrary& library_;
  Diagnostics& diagnostics_;
  std::set<const doc::Port*> reportedValues_;  ///< struct values reported invalid (nodedef defaults are read per use)
  Scope top_;
  std::vector<std::unique_ptr<Scope>> graphScopes_;
  std::unordered_map<std::string_view, Scope*> graphsByName_;
};

void Resolver::createNodes(Scope& scope, const std::vector<const doc::Node*>& nodes) {
  scope.nodes.reserve(scope.nodes.size() + nodes.size());
  scope.resolved->nodes.reserve(scope.resolved->nodes.size() + nodes.size());
  for (const doc::Node* node : nodes) {
    if (node->name.empty()) continue;  // reported by the builder
    auto resolved = std::make_unique<ResolvedNode>();
    resolved->node = node;
    resolved->scope = scope.resolved;
    resolved->nodedef = matchNodeDef(*node, library_, diagnostics_);
    if (resolved->nodedef) resolved->signature = &library_.signature(*resolved->nodedef);
    scope.nodes.emplace(node->name, resolved.get());
    scope.resolved->nodes.push_back(std::move(resolved));
  }
}

void Resolver::checkConnectionType(const doc::Port& port, ResolvedInput& result) {
  const std::string_view from = result.upstream.type;
  if (from.empty()) return;  // the upstream node has no nodedef; its error is already reported
  if (!port.channels.empty()) {
    if (auto problem = checkChannels(port.channels, from, result.type)) {
      diagnostics_.error(port.attributeLocation("channels"),
                         fmt::format("'{}' cannot take channels \"{}\" of a {}: {}", port.name, port.channels, from,
                                     *problem));
    }
    return;
  }
  if (from != result.type) {
    std::string what = result.upstream.node ? fmt::format("node '{}'", result.upstream.node->name())
                                            : fmt::format("node graph '{}'", result.upstream.graph->name());
    diagnostics_.error(port.attributeLocation(result.upstream.node ? "nodename" : "nodegraph"),
                       fmt::format("type mismatch: '{}' is {}, but output '{}' of {} is {}", port.name, result.type,
                                   result.upstream.output, what, from));
  }
}

std::vector<const doc::Token*> Resolver::tokensSeen(const Scope& scope, const std::vector<doc::Token>* own) const {
  std::vector<const doc::Token*> out;
  if (own) {
    for (const doc::Token& t : *own) out.push_back(&t);
  }
  out.insert(out.end(), scope.tokens.begin(), scope.tokens.end());
  if (&scope != &top_) out.insert(out.end(), top_.tokens.begin(), top_.tokens.end());
  return out;
}

void Resolver::resolvePort(const Scope& scope, const doc::Port& port, ResolvedInput& result,
                           const std::vector<doc::Token>* ownTokens, const Scope* tokenScope) {
  result.instance = &port;
  result.location = port.location;
  result.channels = port.channels;
  if (!port.channels.empty() && port.element.valid() &&
      doc::parseVersion(port.element.document().root().attributeOr("version", "")).value_or(doc::Version{1, 39}) >=
          doc::Version{1, 39}) {
    diagnostics_.error(port.attributeLocation("channels"),
                       "the 'channels' attribute is MaterialX 1.38-and-older syntax, removed in 1.39: use <extract>, "
                       "<combine2/3/4> or <convert> nodes");
  }
  // At document level nodes and node graphs share one namespace, and MaterialX finds a graph
  // by `nodename` too (its test suite: cascade_nodegraphs.mtlx connects outputs so).
  const bool nodenameIsGraph = !port.nodename.empty() && !scope.graph && !scope.nodes.contains(port.nodename) &&
                               graphsByName_.contains(port.nodename);
  if (!port.nodename.empty() && !nodenameIsGraph) {
    auto it = scope.nodes.find(port.nodename);
    if (it == scope.nodes.end()) {
      diagnostics_.error(port.attributeLocation("nodename"),
                         fmt::format("'{}' connects to node '{}', which does not exist in {}", port.name, port.nodename,
                                     scope.describe()));
      return;
    }
    ResolvedNode* up = it->second;
    result.source = InputSource::Connection;
    result.upstream.node = up;
    if (!up->signature) {
      result.upstream.output = port.output;
      return;
    }
    const doc::Output* out = nullptr;
    if (!port.output.empty()) {
      out = up->signature->findOutput(port.output);
      if (!out) {
        std::vector<std::string> names;
        for (const doc::Output* o : up->signature->outputs) names.emplace_back(o->name);
        diagnostics_.error(port.attributeLocation("output"),
                           fmt::format("node '{}' has no output '{}' (its outputs: {})", up->name(), port.output,
                                       fmt::join(names, ", ")));
        return;
      }
    } else if (up->signature->outputs.size() == 1) {
      out = up->signature->outputs[0];
    } else {
      std::vector<std::string> names;
      for (const doc::Output* o : up->signature->outputs) names.emplace_back(o->name);
      diagnostics_.error(port.attributeLocation("nodename"),
                         fmt::format("node '{}' has several outputs ({}); name one with output=\"...\"", up->name(),
                                     fmt::join(names, ", ")));
      return;
    }
    result.upstream.output = out->name;
    result.upstream.type = out->type;
    checkConnectionType(port, result);
    return;
  }
  if (!port.nodegraph.empty() || nodenameIsGraph) {
    const std::string_view graphName = nodenameIsGraph ? port.nodename : port.nodegraph;
    const char* graphAttribute = nodenameIsGraph ? "nodename" : "nodegraph";
    if (scope.graph) {
      diagnostics_.error(port.attributeLocation(graphAttribute),
                         fmt::format("'{}' connects to node graph '{}' from inside {}: only document-level elements "
                                     "can connect to a node graph",
                                     port.name, graphName, scope.describe()));
      return;
    }
    auto it = graphsByName_.find(graphName);
    if (it == graphsByName_.end()) {
      diagnostics_.error(port.attributeLocation(graphAttribute),
                         fmt::format("'{}' connects to node graph '{}', which does not exist", port.name, graphName));
      return;
    }
    const ResolvedGraph& graph = *it->second->resolved;
    const doc::NodeGraph& element = *it->second->graph;
    const doc::Output* out = nullptr;
    if (!port.output.empty()) {
      out = element.findOutput(port.output);
    } else if (element.outputs.size() == 1) {
      out = &element.outputs[0];
    }
    if (!out) {
      std::vector<std::string> names;
      for (const doc::Output& o : element.outputs) names.emplace_back(o.name);
      diagnostics_.error(port.attributeLocation(port.output.empty() ? graphAttribute : "output"),
                         port.output.empty()
                             ? fmt::format("node graph '{}' has several outputs ({}); name one with output=\"...\"",
                                           element.name, fmt::join(names, ", "))
                             : fmt::format("node graph '{}' has no output '{}' (its outputs: {})", element.name,
                                           port.output, fmt::join(names, ", ")));
      return;
    }
    result.source = InputSource::Connection;
    result.upstream.graph = &graph;
    result.upstream.output = out->name;
    result.upstream.type = out->type;
    checkConnectionType(port, result);
    return;
  }
  if (!port.interfacename.empty()) {
    const ResolvedInput* iface = scope.resolved->findInterface(port.interfacename);
    if (!iface) {
      std::vector<std::string> names;
      for (const ResolvedInput& i : scope.resolved->interface) names.emplace_back(i.name);
      diagnostics_.error(port.attributeLocation("interfacename"),
                         fmt::format("'{}' refers to interface input '{}', which {} does not have (its interface: {})",
                                     port.name, port.interfacename, scope.describe(),
                                     names.empty() ? std::string("empty") : fmt::format("{}", fmt::join(names, ", "))));
      return;
    }
    result.source = InputSource::Interface;
    result.interfaceName = iface->name;
    if (iface->type != result.type) {
      diagnostics_.error(port.attributeLocation("interfacename"),
                         fmt::format("type mismatch: '{}' is {}, but interface input '{}' of {} is {}", port.name,
                                     result.type, iface->name, scope.describe(), iface->type));
    }
    return;
  }
  if (readStruct(port, result)) {
    result.source = InputSource::Value;
    return;
  }
  // An empty value of a shader or closure type (value="") leaves the input unset.
  if (port.value && port.value->type() != doc::ValueType::None) {
    result.source = InputSource::Value;
    result.value = port.value;
    // Filenames are relative to the enclosing fileprefix, and [token] names the value of a
    // <token> of the enclosing graph (MaterialX 1.39 "Filename Substitutions").
    if (port.value->type() == doc::ValueType::Filename && !port.value->as<std::string>().empty()) {
      std::string path = std::string(port.fileprefix) + port.value->as<std::string>();
      // Each [name] is replaced by the innermost token of that name.
      const std::vector<const doc::Token*> seen = tokensSeen(tokenScope ? *tokenScope : scope, ownTokens);
      size_t open = path.find('[');
      while (open != std::string::npos) {
        const size_t close = path.find(']', open);
        if (close == std::string::npos) break;
        const std::string_view name = std::string_view(path).substr(open + 1, close - open - 1);
        size_t next = open + 1;
        for (const doc::Token* token : seen) {
          if (token->name != name) continue;
          path.replace(open, close - open + 1, token->value);
          next = open + token->value.size();  // past the value: a token's value is not substituted again
          break;
        }
        open = path.find('[', next);
      }
      result.value = doc::Value(doc::ValueType::Filename, std::move(path));
    }
  }
}

bool Resolver::readStruct(const doc::Port& port, ResolvedInput& result) {
  if (!port.valueString || doc::isStandardTypeName(port.type)) return false;
  const lib::StructType* type = library_.structType(port.type);
  const bool empty = port.valueString->find_first_not_of(" \t\n\r") == std::string_view::npos;
  if (!type) {
    // A typedef without members (an opaque type) has no literal values; neither has an
    // unknown type (reported where the type is checked).
    if (!empty && library_.findTypeDef(port.type) && reportedValues_.insert(&port).second) {
      diagnostics_.error(port.valueLocation, fmt::format("invalid {} value \"{}\" for '{}': this type has no literal "
                                                         "values (only structs, typedefs with members, have them)",
                                                         port.type, *port.valueString, port.name));
    }
    return false;
  }
  if (empty) return false;
  auto parsed = lib::parseStructValue(*type, library_, *port.valueString);
  if (auto* error = std::get_if<doc::ValueError>(&parsed)) {
    if (reportedValues_.insert(&port).second) {
      SourceLocation where = port.valueLocation;
      if (where.valid()) where.offset += static_cast<uint32_t>(error->offset);  // no entities in struct literals
      diagnostics_.error(where, fmt::format("invalid {} value \"{}\" for '{}': {}", port.type, *port.valueString,
                                            port.name, error->message));
    }
    return false;
  }
  result.structValue = std::get<std::vector<doc::Value>>(std::move(parsed));
  return true;
}

void Resolver::checkEnum(const ResolvedInput& input) {
  if (!input.declaration || input.source != InputSource::Value || !input.value) return;
  if (input.declaration->enumNames.empty() || !input.declaration->enumValues.empty()) return;
  if (input.value->type() != doc::ValueType::String) return;
  const std::string& value = input.value->as<std::string>();
  std::string_view list = input.declaration->enumNames;
  size_t start = 0;
  while (start <= list.size()) {
    size_t comma = list.find(',', start);
    std::string_view item = list.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    if (item == value) return;
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  diagnostics_.error(input.instance ? input.instance->attributeLocation("value") : input.location,
                     fmt::format("'{}' is \"{}\", which is not one of its allowed values: {}", input.name, value, list));
}

void Resolver::resolveNode(Scope& scope, ResolvedNode& node) {
  if (!node.signature) return;
  for (const doc::Input* declaration : node.signature->inputs) {
    ResolvedInput input = declaredInput(*declaration);
    if (const doc::Input* instance = node.node->findInput(declaration->name)) {
      resolvePort(scope, *instance, input, &node.node->tokens);
    }
    if (input.source == InputSource::Unset) applyDefault(input, *declaration);
    if (input.source == InputSource::Unset && readStruct(*declaration, input)) input.source = InputSource::Default;
    checkEnum(input);
    node.inputs.push_back(std::move(input));
  }
}

void Resolver::resolveInterface(Scope& scope) {
  ResolvedGraph& graph = *scope.resolved;
  if (graph.implements) {
    for (const doc::Input* declaration : library_.signature(*graph.implements).inputs) {
      ResolvedInput input = declaredInput(*declaration);
      applyDefault(input, *declaration);
      if (input.source == InputSource::Unset && readStruct(*declaration, input)) input.source = InputSource::Default;
      graph.interface.push_back(std::move(input));
    }
    return;
  }
  for (const doc::Input* declared : scope.inputs) {
    ResolvedInput input;
    input.name = declared->name;
    input.type = declared->type;
    input.location = declared->location;
    if (!library_.isKnownType(declared->type)) {
      diagnostics_.error(declared->attributeLocation("type"),
                         fmt::format("interface input '{}' has unknown type '{}'", declared->name, declared->type));
    }
    // A document-level graph's interface inputs (and the document's own) take values, or
    // connections to document-level nodes.
    resolvePort(top_, *declared, input, nullptr, &scope);  // with the graph's own tokens
    if (input.source == InputSource::Unset && !declared->defaultgeomprop.empty()) {
      input.source = InputSource::GeomProp;
      input.geomprop = declared->defaultgeomprop;
    }
    graph.interface.push_back(std::move(input));
  }
}

void Resolver::resolveOutputs(Scope& scope) {
  ResolvedGraph& graph = *scope.resolved;
  for (const doc::Output* out : scope.outputs) {
    ResolvedInput output;
    output.name = out->name;
    output.type = out->type;
    output.location = out->location;
    resolvePort(scope, *out, output);
    if (output.source == InputSource::Unset && !out->isConnected()) {
      diagnostics_.warning(out->location, fmt::format("output '{}' of {} is not connected", out->name, scope.describe()));
    }
    graph.outputs.push_back(std::move(output));
  }
  if (graph.implements) {
    for (const doc::Output* declared : library_.signature(*graph.implements).outputs) {
      const ResolvedInput* out = graph.findOutput(declared->name);
      if (!out) {
        diagnostics_.error(scope.graph->location,
                           fmt::format("node graph '{}' implements nodedef '{}' but has no output '{}'",
                                       scope.graph->name, graph.implements->name, declared->name));
      } else if (out->type != declared->type) {
        diagnostics_.error(out->location, fmt::format("output '{}' is {}, but nodedef '{}' declares it {}", out->name,
                                                      out->type, graph.implements->name, declared->type));
      }
    }
  }
}

void Resolver::followInto(const ResolvedInput& input, const ResolvedInput& via, std::vector<Dependency>& out, int depth) {
  // Graph outputs and interface inputs are pass-throughs; follow them to the nodes behind.
  // `depth` bounds the walk so a malformed chain of graphs cannot loop.
  if (depth > 64) return;
  if (input.source == InputSource::Connection) {
    if (input.upstream.node) {
      out.push_back({const_cast<ResolvedNode*>(input.upstream.node), &via});
    } else if (input.upstream.graph) {
      if (const ResolvedInput* o = input.upstream.graph->findOutput(input.upstream.output)) followInto(*o, via, out, depth + 1);
    }
  }
}

std::vector<Dependency> Resolver::dependencies(ResolvedNode& node) {
  std::vector<Dependency> out;
  for (const ResolvedInput& input : node.inputs) {
    if (input.source == InputSource::Interface) {
      if (const ResolvedInput* iface = node.scope->findInterface(input.interfaceName)) followInto(*iface, input, out, 0);
    } else {
      followInto(input, input, out, 0);
    }
  }
  return out;
}

void Resolver::order(std::vector<Scope*>& scopes) {
  // Iterative depth-first search (a long chain of nodes must not overflow the call stack):
  // post-order gives producers before consumers; an edge back to a node on the stack is a cycle.
  enum class Mark : uint8_t { None, Active, Done };
  std::unordered_map<const ResolvedNode*, Mark> marks;
  std::vector<ResolvedNode*> sorted;
  struct Frame {
    ResolvedNode* node;
    std::vector<Dependency> deps;
    size_t next = 0;
  };
  for (Scope* scope : scopes) {
    for (auto& root : scope->resolved->nodes) {
      if (marks[root.get()] != Mark::None) continue;
      std::vector<Frame> stack;
      stack.push_back({root.get(), dependencies(*root)});
      marks[root.get()] = Mark::Active;
      while (!stack.empty()) {
        Frame& frame = stack.back();
        if (frame.next < frame.deps.size()) {
          Dependency dep = frame.deps[frame.next++];
          Mark& mark = marks[dep.node];
          if (mark == Mark::None) {
            mark = Mark::Active;
            std::vector<Dependency> deps = dependencies(*dep.node);
            stack.push_back({dep.node, std::move(deps)});
          } else if (mark == Mark::Active) {
            std::string path;
            bool on = false;
            for (const Frame& f : stack) {
              if (f.node == dep.node) on = true;
              if (on) path += std::string(f.node->name()) + " -> ";
            }
            path += dep.node->name();
            diagnostics_.error(dep.input->location,
                               fmt::format("cycle: {} (through input '{}' of node '{}')", path, dep.input->name,
                                           frame.node->name()));
          }
          continue;
        }
        marks[frame.node] = Mark::Done;
        sorted.push_back(frame.node);
        stack.pop_back();
      }
    }
  }
  std::unordered_map<const ResolvedNode*, size_t> position;
  for (size_t i = 0; i < sorted.size(); ++i) position[sorted[i]] = i;
  for (Scope* scope : scopes) {
    auto& nodes = scope->resolved->nodes;
    std::stable_sort(nodes.begin(), nodes.end(), [&](const auto& a, const auto& b) {
      return position[a.get()] < position[b.get()];
    });
  }
}

void Resolver::resolve(ResolvedGraph& top, const TopLevel& topLevel, std::vector<std::unique_ptr<ResolvedGraph>>& graphs,
                       const std::vector<const doc::NodeGraph*>& docGraphs) {
  top_.resolved = &top;
  top_.inputs = topLevel.inputs;
  top_.outputs = topLevel.outputs;
  top_.tokens = topLevel.tokens;
  for (const doc::NodeGraph* g : docGraphs) {
    if (g->name.empty()) continue;
    auto resolved = std::make_unique<ResolvedGraph>();
    resolved->graph = g;
    resolved->implements = library_.implementedNodeDef(*g);
    if (!g->nodedef.empty() || resolved->implements) {
      if (!resolved->implements) {
        diagnostics_.error(g->element.valid() ? g->element.location() : g->location,
                           fmt::format("node graph '{}' implements nodedef '{}', which is not defined", g->name,
                                       g->nodedef));
      } else if (!g->inputs.empty()) {
        diagnostics_.error(g->inputs.front().location,
                           fmt::format("node graph '{}' implements nodedef '{}' and so takes its interface from it; "
                                       "it cannot declare inputs of its own",
                                       g->name, g->nodedef));
      }
    }
    auto scope = std::make_unique<Scope>();
    scope->resolved = resolved.get();
    scope->graph = g;
    for (const doc::Input& i : g->inputs) scope->inputs.push_back(&i);
    for (const doc::Output& o : g->outputs) scope->outputs.push_back(&o);
    for (const doc::Token& t : g->tokens) scope->tokens.push_back(&t);
    // A graph that implements a nodedef sees the nodedef's tokens (their defaults) after its own.
    if (resolved->implements) {
      for (const doc::Token& t : resolved->implements->tokens) scope->tokens.push_back(&t);
    }
    graphsByName_.emplace(g->name, scope.get());
    graphScopes_.push_back(std::move(scope));
    graphs.push_back(std::move(resolved));
  }
  createNodes(top_, topLevel.nodes);
  for (auto& scope : graphScopes_) {
    std::vector<const doc::Node*> nodes;
    for (const doc::Node& n : scope->graph->nodes) nodes.push_back(&n);
    createNodes(*scope, nodes);
  }
  resolveInterface(top_);
  for (auto& scope : graphScopes_) resolveInterface(*scope);
  for (auto& node : top.nodes) resolveNode(top_, *node);
  resolveOutputs(top_);
  for (auto& scope : graphScopes_) {
    for (auto& node : scope->resolved->nodes) resolveNode(*scope, *node);
    resolveOutputs(*scope);
  }
  std::vector<Scope*> scopes{&top_};
  for (auto& scope : graphScopes_) scopes.push_back(scope.get());
  order(scopes);
}

/// The document and every document it includes, includes first, each once.
void collectDocuments(const doc::Document& document, std::vector<const doc::Document*>& out) {
  if (std::find(out.begin(), out.end(), &document) != out.end()) return;
  for (const doc::Include& include : document.includes) {
    if (include.document) collectDocuments(*include.document, out);
  }
  out.push_back(&document);
}

}  // namespace

ResolvedDocument resolveDocument(const doc::Document& document, const lib::NodeLibrary& library,
                                 Diagnostics& diagnostics) {
  ResolvedDocument result;
  result.document = &document;
  collectDocuments(document, result.documents);
  result.definitions = std::make_unique<lib::NodeLibrary>(&library);
  for (const doc::Document* d : result.documents) result.definitions->addDocument(*d, diagnostics);
  result.definitions->finalize(diagnostics);

  // Names at document level must be unique across the document and its includes.
  std::unordered_map<std::string_view, SourceLocation> names;
  TopLevel topLevel;
  std::vector<const doc::NodeGraph*> graphs;
  auto claim = [&](std::string_view name, SourceLocation location) {
    auto [it, inserted] = names.emplace(name, location);
    if (!inserted && it->second.file != location.file) {
      diagnostics.error(location, fmt::format("'{}' is also defined at {} (an included document uses the same name)",
                                              name, it->second.str()));
    }
  };
  // Each document-level element claims its name and joins its list.
  auto gather = [&](const auto& elements, auto& into) {
    for (const auto& e : elements) {
      claim(e.name, e.location);
      into.push_back(&e);
    }
  };
  for (const doc::Document* d : result.documents) {
    gather(d->nodes, topLevel.nodes);
    gather(d->inputs, topLevel.inputs);
    gather(d->outputs, topLevel.outputs);
    gather(d->tokens, topLevel.tokens);
    gather(d->nodegraphs, graphs);
  }
  Resolver(*result.definitions, diagnostics).resolve(result.top, topLevel, result.graphs, graphs);

  for (const auto& node : result.top.nodes) {
    if (!node->signature || node->signature->outputType() != "material") continue;
    ResolvedMaterial material;
    material.node = node.get();
    for (const ResolvedInput& input : node->inputs) {
      if (input.source != InputSource::Connection) continue;
      const ResolvedNode* shader = input.upstream.node;
      if (!shader && input.upstream.graph) {
        // A shader produced inside a graph: the node feeding that graph output.
        const ResolvedInput* out = input.upstream.graph->findOutput(input.upstream.output);
        if (out && out->source == InputSource::Connection) shader = out->upstream.node;
      }
      if (shader) material.shaders.push_back({input.name, shader});
    }
    result.materials.push_back(std::move(material));
  }
  return result;
}

std::unique_ptr<ResolvedGraph> resolveImplementation(const doc::NodeGraph& graph, const lib::NodeLibrary& library,
                                                     Diagnostics& diagnostics) {
  ResolvedGraph top;
  std::vector<std::unique_ptr<ResolvedGraph>> graphs;
  Resolver(library, diagnostics).resolve(top, {}, graphs, {&graph});
  return graphs.empty() ? nullptr : std::move(graphs.front());
}

}  // namespace mxc::resolve
