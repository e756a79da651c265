#include "compiler/library/NodeLibrary.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>

namespace mxc::lib {

const doc::Input* Signature::findInput(std::string_view name) const {
  for (const doc::Input* in : inputs) {
    if (in->name == name) return in;
  }
  return nullptr;
}

const doc::Output* Signature::findOutput(std::string_view name) const {
  for (const doc::Output* out : outputs) {
    if (out->name == name) return out;
  }
  return nullptr;
}

std::string_view Signature::outputType() const {
  if (outputs.size() == 1) return outputs[0]->type;
  return "multioutput";
}

template <typename T>
void NodeLibrary::define(std::unordered_map<std::string_view, const T*>& table, const T& item, std::string_view kind,
                         Diagnostics& diagnostics) {
  auto [it, inserted] = table.emplace(item.name, &item);
  if (!inserted) {
    diagnostics.error(item.location, fmt::format("{} '{}' is defined twice (also at {})", kind, item.name,
                                                 it->second->location.str()));
  }
}

void NodeLibrary::addDocument(const doc::Document& document, Diagnostics& diagnostics) {
  documents_.push_back(&document);
  for (const doc::NodeDef& nd : document.nodedefs) {
    if (nd.name.empty()) continue;  // reported by the builder
    // A nodedef without `node` defines no category, but is one by name: a node graph can
    // implement it (MaterialX reads it so; its test suite's _options.mtlx keeps settings in one).
    const size_t before = nodedefs_.size();
    define(nodedefs_, nd, "nodedef", diagnostics);
    if (nodedefs_.size() > before) (nd.node.empty() ? withoutCategory_ : byCategory_[nd.node]).push_back(&nd);
  }
  for (const doc::NodeGraph& g : document.nodegraphs) {
    if (g.name.empty()) continue;
    graphs_.emplace(g.name, &g);
    if (!g.nodedef.empty()) {
      auto [it, inserted] = implementations_.emplace(g.nodedef, &g);
      if (!inserted && it->second != &g) {
        diagnostics.error(g.location, fmt::format("nodedef '{}' has two node-graph implementations: '{}' and '{}' "
                                                  "(at {})",
                                                  g.nodedef, g.name, it->second->name, it->second->location.str()));
      }
    }
  }
  for (const doc::TypeDef& t : document.typedefs) {
    // The standard types are declared by every MaterialX standard library; the same typedef
    // from two library files is harmless, so only the first is kept.
    typedefs_.emplace(t.name, &t);
  }
  for (const doc::GeomPropDef& g : document.geompropdefs) geomprops_.emplace(g.name, &g);
}

void NodeLibrary::finalize(Diagnostics& diagnostics) {
  // Implementations naming a graph.
  for (const doc::Document* document : documents_) {
    for (const doc::Implementation& impl : document->implementations) {
      if (!impl.sourcecode.empty()) {
        inlineSources_.emplace(fmt::format("{}|{}", impl.nodedef, impl.target), &impl);
        continue;
      }
      if (impl.nodegraph.empty()) continue;  // implementations in source files are not used by mxc
      const doc::NodeGraph* graph = nullptr;
      for (const NodeLibrary* layer = this; layer && !graph; layer = layer->parent_) {
        if (auto it = layer->graphs_.find(impl.nodegraph); it != layer->graphs_.end()) graph = it->second;
      }
      if (!graph) {
        diagnostics.error(impl.location, fmt::format("implementation '{}' names node graph '{}', which is not defined",
                                                     impl.name, impl.nodegraph));
        continue;
      }
      if (!findNodeDef(impl.nodedef)) {
        diagnostics.error(impl.location, fmt::format("implementation '{}' is for nodedef '{}', which is not defined",
                                                     impl.name, impl.nodedef));
        continue;
      }
      implementations_.emplace(impl.nodedef, graph);
      implemented_.emplace(graph, impl.nodedef);  // the first implementation naming a graph wins
    }
  }
  for (auto& [nodedefName, graph] : implementations_) {
    if (!findNodeDef(nodedefName)) {
      diagnostics.error(graph->element.valid() ? graph->location : SourceLocation{},
                        fmt::format("node graph '{}' implements nodedef '{}', which is not defined", graph->name,
                                    nodedefName));
    }
  }

  // Struct types, in document order so messages come out the same every run.
  for (const doc::Document* document : documents_) {
    for (const doc::TypeDef& t : document->typedefs) {
      if (auto it = typedefs_.find(t.name); it == typedefs_.end() || it->second != &t || t.members.empty()) continue;
      std::vector<std::string_view> building;
      buildStructType(t, building, diagnostics);
    }
  }

  // Signatures with inheritance, in a fixed order so messages come out the same every run.
  std::vector<const doc::NodeDef*> ordered;
  for (const doc::Document* document : documents_) {
    for (const doc::NodeDef& nd : document->nodedefs) {
      if (auto it = nodedefs_.find(nd.name); it != nodedefs_.end() && it->second == &nd) ordered.push_back(&nd);
    }
  }
  for (const doc::NodeDef* nd : ordered) {
    // The inheritance chain, most derived first.
    std::vector<const doc::NodeDef*> chain{nd};
    std::set<const doc::NodeDef*> seen{nd};
    bool broken = false;
    while (!chain.back()->inherit.empty()) {
      const doc::NodeDef* base = findNodeDef(chain.back()->inherit);
      if (!base) {
        diagnostics.error(chain.back()->element.valid() ? chain.back()->location : SourceLocation{},
                          fmt::format("nodedef '{}' inherits from '{}', which is not defined", chain.back()->name,
                                      chain.back()->inherit));
        broken = true;
        break;
      }
      if (!seen.insert(base).second) {
        diagnostics.error(nd->location, fmt::format("nodedef '{}' inherits from itself through '{}'", nd->name,
                                                    chain.back()->name));
        broken = true;
        break;
      }
      chain.push_back(base);
    }
    Signature sig;
    if (broken) chain.resize(1);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      for (const doc::Input& in : (*it)->inputs) {
        auto same = std::find_if(sig.inputs.begin(), sig.inputs.end(), [&](const doc::Input* x) { return x->name == in.name; });
        if (same != sig.inputs.end()) {
          *same = &in;
        } else {
          sig.inputs.push_back(&in);
        }
      }
      for (const doc::Output& out : (*it)->outputs) {
        auto same = std::find_if(sig.outputs.begin(), sig.outputs.end(), [&](const doc::Output* x) { return x->name == out.name; });
        if (same != sig.outputs.end()) {
          *same = &out;
        } else {
          sig.outputs.push_back(&out);
        }
      }
    }
    for (const doc::Input* in : sig.inputs) {
      if (!isKnownType(in->type)) {
        diagnostics.error(in->location, fmt::format("input '{}' of nodedef '{}' has unknown type '{}'", in->name,
                                                    nd->name, in->type));
      }
      if (!in->defaultgeomprop.empty() && !findGeomPropDef(in->defaultgeomprop)) {
        diagnostics.error(in->attributeLocation("defaultgeomprop"),
                          fmt::format("input '{}' of nodedef '{}' defaults to geometric property '{}', which no "
                                      "geompropdef defines",
                                      in->name, nd->name, in->defaultgeomprop));
      }
    }
    if (sig.outputs.empty() && !nd->node.empty()) {  // one of no category makes no node (_options.mtlx)
      diagnostics.error(nd->location, fmt::format("nodedef '{}' declares no <output> and inherits none", nd->name));
    }
    for (const doc::Output* out : sig.outputs) {
      if (!isKnownType(out->type)) {
        diagnostics.error(out->location, fmt::format("output '{}' of nodedef '{}' has unknown type '{}'", out->name,
                                                     nd->name, out->type));
      }
    }
    signatures_.emplace(nd, std::move(sig));
  }
}

std::vector<const doc::NodeDef*> NodeLibrary::nodeDefsWithoutCategory() const {
  std::vector<const doc::NodeDef*> out;
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    out.insert(out.end(), layer->withoutCategory_.begin(), layer->withoutCategory_.end());
  }
  return out;
}

const doc::NodeDef* NodeLibrary::findNodeDef(std::string_view name) const {
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->nodedefs_.find(name); it != layer->nodedefs_.end()) return it->second;
  }
  return nullptr;
}

std::vector<const doc::NodeDef*> NodeLibrary::nodeDefsFor(std::string_view category) const {
  std::vector<const doc::NodeDef*> out;
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    auto it = layer->byCategory_.find(category);
    if (it == layer->byCategory_.end()) continue;
    for (const doc::NodeDef* nd : it->second) {
      if (findNodeDef(nd->name) == nd) out.push_back(nd);  // skip definitions shadowed by a later layer
    }
  }
  return out;
}

bool NodeLibrary::hasCategory(std::string_view category) const {
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (layer->byCategory_.count(category)) return true;
  }
  return false;
}

std::vector<std::string_view> NodeLibrary::categories() const {
  std::set<std::string_view> all;
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    for (const auto& [category, defs] : layer->byCategory_) all.insert(category);
  }
  return {all.begin(), all.end()};
}

const Signature* NodeLibrary::findSignature(const doc::NodeDef& nodedef) const {
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->signatures_.find(&nodedef); it != layer->signatures_.end()) return &it->second;
  }
  return nullptr;
}

const Signature& NodeLibrary::signature(const doc::NodeDef& nodedef) const {
  if (const Signature* s = findSignature(nodedef)) return *s;
  // A nodedef no layer finalised (finalize not called yet) gets its own ports, without inheritance.
  Signature& sig = signatures_[&nodedef];
  for (const doc::Input& in : nodedef.inputs) sig.inputs.push_back(&in);
  for (const doc::Output& out : nodedef.outputs) sig.outputs.push_back(&out);
  return sig;
}

const doc::NodeGraph* NodeLibrary::implementationGraph(const doc::NodeDef& nodedef) const {
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->implementations_.find(nodedef.name); it != layer->implementations_.end()) return it->second;
  }
  return nullptr;
}

const doc::NodeDef* NodeLibrary::implementedNodeDef(const doc::NodeGraph& graph) const {
  if (!graph.nodedef.empty()) return findNodeDef(graph.nodedef);
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->implemented_.find(&graph); it != layer->implemented_.end()) return findNodeDef(it->second);
  }
  return nullptr;
}

const StructType* NodeLibrary::buildStructType(const doc::TypeDef& t, std::vector<std::string_view>& building,
                                                Diagnostics& diagnostics) {
  if (auto it = structs_.find(t.name); it != structs_.end()) return it->second.get();
  if (std::find(building.begin(), building.end(), t.name) != building.end()) {
    diagnostics.error(t.location, fmt::format("struct '{}' contains itself (through {})", t.name,
                                              fmt::join(building, " -> ")));
    structs_.emplace(t.name, nullptr);
    return nullptr;
  }
  building.push_back(t.name);
  auto type = std::make_unique<StructType>();
  type->name = t.name;
  bool ok = true;
  for (const doc::TypeDef::Member& m : t.members) {
    StructType::Member member{m.name, m.type, type->leaves.size(), 0};
    const StructType* inner = nullptr;
    if (auto it = typedefs_.find(m.type); it != typedefs_.end() && !it->second->members.empty()) {
      inner = buildStructType(*it->second, building, diagnostics);
      if (!inner) ok = false;
    } else if (!doc::isStandardTypeName(m.type)) {
      inner = parent_ ? parent_->structType(m.type) : nullptr;
      if (!inner) {
        diagnostics.error(m.location, fmt::format("member '{}' of struct '{}' has type '{}', which is neither a value "
                                                  "type nor a struct",
                                                  m.name, t.name, m.type));
        ok = false;
      }
    } else if (doc::valueTypeOf(m.type) == doc::ValueType::None) {
      diagnostics.error(m.location, fmt::format("member '{}' of struct '{}' has type '{}', which has no values (a "
                                                "struct holds values)",
                                                m.name, t.name, m.type));
      ok = false;
    }
    if (!ok) continue;
    if (inner) {
      // A struct member's defaults: its own `value` (a struct literal), else its members'.
      std::vector<doc::Value> defaults;
      if (m.valueString) {
        auto parsed = parseStructValue(*inner, *this, *m.valueString);
        if (auto* error = std::get_if<doc::ValueError>(&parsed)) {
          diagnostics.error(m.location, fmt::format("member '{}' of struct '{}': invalid value \"{}\": {}", m.name,
                                                    t.name, *m.valueString, error->message));
        } else {
          defaults = std::get<std::vector<doc::Value>>(std::move(parsed));
        }
      }
      for (size_t i = 0; i < inner->leaves.size(); ++i) {
        StructType::Leaf leaf = inner->leaves[i];
        leaf.path = fmt::format("{}.{}", m.name, leaf.path);
        if (!defaults.empty()) leaf.defaultValue = defaults[i];
        type->leaves.push_back(std::move(leaf));
      }
    } else {
      StructType::Leaf leaf{std::string(m.name), doc::valueTypeOf(m.type), std::nullopt};
      if (m.valueString) {
        doc::ValueError error;
        leaf.defaultValue = doc::tryParseValue(leaf.type, *m.valueString, &error);
        if (!leaf.defaultValue) {
          diagnostics.error(m.location, fmt::format("member '{}' of struct '{}': invalid {} value \"{}\": {}", m.name,
                                                    t.name, m.type, *m.valueString, error.message));
        }
      }
      type->leaves.push_back(std::move(leaf));
    }
    member.leafCount = type->leaves.size() - member.firstLeaf;
    type->members.push_back(member);
  }
  building.pop_back();
  if (!ok) type.reset();
  return structs_.emplace(t.name, std::move(type)).first->second.get();
}

const StructType* NodeLibrary::structType(std::string_view name) const {
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->structs_.find(name); it != layer->structs_.end()) return it->second.get();
    if (layer->typedefs_.count(name)) return nullptr;  // a typedef without members shadows
  }
  return nullptr;
}

const doc::Implementation* NodeLibrary::inlineImplementation(const doc::NodeDef& nodedef,
                                                             std::string_view target) const {
  const std::string key = fmt::format("{}|{}", nodedef.name, target);
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->inlineSources_.find(key); it != layer->inlineSources_.end()) return it->second;
  }
  return nullptr;
}

const doc::TypeDef* NodeLibrary::findTypeDef(std::string_view name) const {
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->typedefs_.find(name); it != layer->typedefs_.end()) return it->second;
  }
  return nullptr;
}

bool NodeLibrary::isKnownType(std::string_view name) const {
  return doc::isStandardTypeName(name) || findTypeDef(name) != nullptr;
}

const doc::GeomPropDef* NodeLibrary::findGeomPropDef(std::string_view name) const {
  for (const NodeLibrary* layer = this; layer; layer = layer->parent_) {
    if (auto it = layer->geomprops_.find(name); it != layer->geomprops_.end()) return it->second;
  }
  return nullptr;
}

}  // namespace mxc::lib
