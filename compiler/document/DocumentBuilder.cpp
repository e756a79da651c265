#include "compiler/document/DocumentBuilder.h"

#include <type_traits>
#include <unordered_map>

#include <fmt/format.h>

#include "compiler/common/Quote.h"

namespace mxc::doc {

namespace {

// Elements of the MaterialX specification that are not nodes and that mxc keeps without acting
// on them (geometry binding and property assignment belong to the renderer, not the shader).
constexpr std::string_view kKeptElements[] = {
    "geominfo", "collection", "propertyset", "propertysetassign", "variantset", "variant",
    "variantassign", "attributedef", "targetdef", "backdrop", "lookgroup", "unittypedef",
};

bool isKeptElement(std::string_view name) {
  for (std::string_view k : kKeptElements) {
    if (k == name) return true;
  }
  return false;
}

/// MaterialX names: a letter or '_' then letters, digits and '_' (':' separates namespaces).
bool isValidName(std::string_view name) {
  if (name.empty()) return false;
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!letter(name[0])) return false;
  for (char c : name) {
    if (!letter(c) && !(c >= '0' && c <= '9') && c != ':') return false;
  }
  return true;
}

/// Effective inherited attributes (colorspace, fileprefix) of the enclosing elements.
struct Scope {
  std::string_view colorspace;
  std::string_view fileprefix;
  std::string_view ns;  ///< MaterialX `namespace`, inherited like the other two

  Scope enter(const xml::Element& e) const {
    Scope s = *this;
    if (auto cs = e.attribute("colorspace")) s.colorspace = *cs;
    if (auto fp = e.attribute("fileprefix")) s.fileprefix = *fp;
    if (auto n = e.attribute("namespace")) s.ns = *n;
    return s;
  }
};

/// Tracks names of sibling elements so a duplicate is reported with the first definition.
/// Most scopes are a node's few inputs: those are searched in a small vector, without a hash
/// table per node; past kLinear names the set switches to a hash table, so a document of
/// many thousand nodes stays linear.
class NameSet {
 public:
  NameSet(Diagnostics& diagnostics, std::string scope) : diagnostics_(diagnostics), scope_(std::move(scope)) {}
  /// For a scope known to hold many names (the document's top level).
  void reserve(size_t count) {
    if (count > kLinear) {
      index_.reserve(count);
      index_.insert(few_.begin(), few_.end());
    }
  }
  void add(std::string_view name, SourceLocation location) {
    if (name.empty()) return;
    const SourceLocation* first = nullptr;
    if (index_.empty()) {
      for (const auto& [seen, where] : few_) {
        if (seen == name) first = &where;
      }
      if (!first) {
        few_.emplace_back(name, location);
        if (few_.size() > kLinear) index_.insert(few_.begin(), few_.end());
      }
    } else {
      auto [it, inserted] = index_.emplace(name, location);
      if (!inserted) first = &it->second;
    }
    if (first) {
      LineColumn at = first->lineColumn();
      diagnostics_.error(location, fmt::format("duplicate name '{}' in {} (first defined at line {}, column {})", name,
                                               scope_, at.line, at.column));
    }
  }

 private:
  static constexpr size_t kLinear = 16;
  Diagnostics& diagnostics_;
  std::string scope_;
  std::vector<std::pair<std::string_view, SourceLocation>> few_;
  std::unordered_map<std::string_view, SourceLocation> index_;
};

class Builder {
 public:
  Builder(Document& document, Diagnostics& diagnostics) : doc_(document), diagnostics_(diagnostics) {}

  void build();

 private:
  SourceLocation at(const xml::Element& e) const { return e.location(); }
  SourceLocation valueAt(const xml::Element& e, std::string_view attribute) const {
    if (const xml::Attribute* a = e.findAttribute(attribute)) return e.document().locationOf(a->valueOffset);
    return e.location();
  }
  /// The `name` attribute, checked: present and a valid MaterialX name.
  std::string_view requireName(const xml::Element& e);
  std::string_view requireAttribute(const xml::Element& e, std::string_view attribute, std::string_view why);
  bool parseBool(const xml::Element& e, std::string_view attribute);

  template <typename PortT>
  PortT buildPort(const xml::Element& e, const Scope& scope);
  Token buildToken(const xml::Element& e);
  /// Reads the <input>/<output>/<token> children of a node, nodedef or graph; other children
  /// go to `other` when given, else are errors.
  /// Adds `child` to the owner's inputs, outputs or tokens when it is one of those (false
  /// otherwise): for nodes, nodedefs, node graphs and the document itself.
  template <typename Owner>
  bool addPort(const xml::Element& child, const Scope& scope, Owner& owner, NameSet& names);
  template <typename Owner>
  void buildPorts(const xml::Element& e, const Scope& scope, Owner& owner, NameSet& names,
                  std::vector<xml::Element>* other);
  Node buildNode(const xml::Element& e, const Scope& scope);
  NodeDef buildNodeDef(const xml::Element& e, const Scope& scope);
  NodeGraph buildNodeGraph(const xml::Element& e, const Scope& scope);
  LegacyMaterial buildLegacyMaterial(const xml::Element& e, const Scope& scope);
  /// A type name as 1.38 writes it: MaterialX 1.22's `vector` is vector3, 1.34's `matrix` is
  /// matrix44, and 1.37's `color2` is vector2 (MaterialX's upgrade rules); other names are kept.
  std::string_view currentType(std::string_view type) const {
    if (!legacy_) return type;
    if (type == "vector") return "vector3";
    if (type == "matrix") return "matrix44";
    if (type == "color2") return "vector2";
    return type;
  }
  /// `name` in the scope's namespace ("ns:name"; MaterialX 1.39 "Namespaces"): the name a
  /// definition is known by, and the name a reference from inside the namespace means. A name
  /// already qualified, or outside any namespace, is kept.
  std::string_view qualified(const Scope& scope, std::string_view name) {
    if (scope.ns.empty() || name.empty() || name.find(':') != std::string_view::npos) return name;
    return doc_.own(fmt::format("{}:{}", scope.ns, name));
  }
  void unexpectedChild(const xml::Element& child, std::string_view parentKind);

  Document& doc_;
  Diagnostics& diagnostics_;
  /// A MaterialX 1.37-or-older document: its legacy elements (<parameter>, <material>,
  /// <shaderref>, <shader>, <opgraph>) are read for upgradeTo138 instead of being refused.
  bool legacy_ = false;
};

std::string_view Builder::requireName(const xml::Element& e) {
  auto name = e.attribute("name");
  if (!name) {
    diagnostics_.error(at(e), fmt::format("<{}> has no 'name' attribute", e.name()));
    return {};
  }
  if (!isValidName(*name)) {
    diagnostics_.error(valueAt(e, "name"),
                       fmt::format("invalid name '{}': a name starts with a letter or '_' and holds only letters, "
                                   "digits and '_'",
                                   *name));
  }
  return *name;
}

std::string_view Builder::requireAttribute(const xml::Element& e, std::string_view attribute, std::string_view why) {
  auto value = e.attribute(attribute);
  if (!value || value->empty()) {
    diagnostics_.error(at(e), fmt::format("<{} name=\"{}\"> has no '{}' attribute ({})", e.name(),
                                          e.attributeOr("name", ""), attribute, why));
    return {};
  }
  return *value;
}

bool Builder::parseBool(const xml::Element& e, std::string_view attribute) {
  auto value = e.attribute(attribute);
  if (!value) return false;
  if (*value == "true") return true;
  if (*value != "false") {
    diagnostics_.error(valueAt(e, attribute),
                       fmt::format("'{}' must be true or false, not '{}'", attribute, *value));
  }
  return false;
}

template <typename PortT>
PortT Builder::buildPort(const xml::Element& e, const Scope& outer) {
  Scope scope = outer.enter(e);
  PortT port;
  port.element = e;
  port.location = at(e);
  port.name = requireName(e);
  port.type = currentType(requireAttribute(e, "type", "every input and output declares its type"));
  port.nodename = e.attributeOr("nodename", "");
  port.nodegraph = e.attributeOr("nodegraph", "");
  port.output = e.attributeOr("output", "");
  port.interfacename = e.attributeOr("interfacename", "");
  port.channels = e.attributeOr("channels", "");
  port.defaultgeomprop = e.attributeOr("defaultgeomprop", "");
  port.defaultinput = e.attributeOr("defaultinput", "");
  port.colorspace = scope.colorspace;
  port.fileprefix = scope.fileprefix;
  port.unit = e.attributeOr("unit", "");
  port.unittype = e.attributeOr("unittype", "");
  port.enumNames = e.attributeOr("enum", "");
  port.enumValues = e.attributeOr("enumvalues", "");
  port.uniform = parseBool(e, "uniform");

  if (!port.nodename.empty() && !port.nodegraph.empty()) {
    diagnostics_.error(port.attributeLocation("nodegraph"),
                       fmt::format("'{}' connects to both node '{}' and node graph '{}'; give one", port.name,
                                   port.nodename, port.nodegraph));
  }
  if (!port.interfacename.empty() && (!port.nodename.empty() || !port.nodegraph.empty())) {
    diagnostics_.error(port.attributeLocation("interfacename"),
                       fmt::format("'{}' has both an interfacename and a node connection; give one", port.name));
  }

  // MaterialX 1.22-1.26 connected a node's input by a parameter of type `opgraphnode` whose
  // value names the node (1.34 made it a nodename); its type, the node's, is set by the upgrade.
  const bool nodeReference = legacy_ && port.type == "opgraphnode";
  if (nodeReference) port.nodename = e.attributeOr("value", "");

  // Outputs of nodedefs give `default` where inputs give `value`. An output default may name a
  // geometric property instead of a value (ND_flake2d's flakenormal defaults to "Nworld").
  const xml::Attribute* valueAttribute = nodeReference ? nullptr : e.findAttribute("value");
  if (const xml::Attribute* d = e.findAttribute("default"); d && !valueAttribute && !nodeReference) {
    if (std::is_same_v<PortT, Output> && isValidName(d->value) && componentCount(valueTypeOf(port.type)) > 1) {
      port.defaultgeomprop = d->value;
    } else {
      valueAttribute = d;
    }
  }
  // An empty value of a type that has no empty literal (a number, a boolean) is no value:
  // MaterialX reads `default=""` so, and its own library writes it (stdlib_genosl_impl.mtlx).
  if (valueAttribute && valueAttribute->value.find_first_not_of(" \t\n\r") == std::string::npos && !port.type.empty() &&
      std::holds_alternative<ValueError>(parseValue(valueTypeOf(port.type), valueAttribute->value))) {
    valueAttribute = nullptr;
  }
  if (valueAttribute) {
    port.valueString = valueAttribute->value;
    port.valueLocation = e.document().locationOf(valueAttribute->valueOffset);
    // A value of a typedef'd type is a struct literal: read by the resolver, which knows the
    // typedef's members (the typedef may come from a library).
    if (!port.type.empty() && isStandardTypeName(port.type)) {
      ValueError error;
      ValueError ignored;
      port.value = tryParseValue(valueTypeOf(port.type), valueAttribute->value, &error, &ignored);
      // Point inside the value when it was not rewritten by entity decoding.
      auto inside = [&](size_t offset) {
        return e.document().locationOf(valueAttribute->valueOffset + (valueAttribute->decoded ? 0u : static_cast<uint32_t>(offset)));
      };
      if (!port.value) {
        diagnostics_.error(inside(error.offset), fmt::format("invalid {} value {} for '{}': {}", port.type,
                                                             quotedValue(valueAttribute->value), port.name, error.message));
      } else if (!ignored.message.empty()) {
        diagnostics_.warning(inside(ignored.offset), fmt::format("{} value {} for '{}': {}", port.type,
                                                                 quotedValue(valueAttribute->value), port.name, ignored.message));
      }
    }
  }
  for (const xml::Element& child : e.children()) {
    // MaterialX 1.22-1.26 connected a graph output by its child <parameter name="in"
    // type="opgraphnode" value="NODE"/> (1.34 made it the output's nodename).
    if (legacy_ && std::is_same_v<PortT, Output> && child.name() == "parameter" &&
        child.attributeOr("type", "") == "opgraphnode") {
      if (child.attributeOr("name", "") == "in") port.nodename = child.attributeOr("value", "");
      continue;
    }
    unexpectedChild(child, e.name());
  }
  return port;
}

Token Builder::buildToken(const xml::Element& e) {
  Token token;
  token.location = at(e);
  token.name = requireName(e);
  token.type = e.attributeOr("type", "string");
  token.value = e.attributeOr("value", "");
  return token;
}

void Builder::unexpectedChild(const xml::Element& child, std::string_view parentKind) {
  if (child.name() == "parameter") {
    diagnostics_.error(at(child), fmt::format("<parameter> is MaterialX 1.37 syntax; since 1.38 it is written <input>"));
    return;
  }
  diagnostics_.error(at(child), fmt::format("unexpected <{}> inside <{}>", child.name(), parentKind));
}

template <typename Owner>
bool Builder::addPort(const xml::Element& child, const Scope& scope, Owner& owner, NameSet& names) {
  const std::string_view kind = child.name();
  if (kind == "input" || (legacy_ && kind == "parameter")) {
    // A 1.37 <parameter> is an input; on a nodedef it was a uniform one (MaterialX's 1.38
    // upgrade marks it so).
    owner.inputs.push_back(buildPort<Input>(child, scope));
    if constexpr (std::is_same_v<Owner, NodeDef>) {
      if (kind == "parameter") owner.inputs.back().uniform = true;
    }
    names.add(owner.inputs.back().name, at(child));
  } else if (kind == "output") {
    owner.outputs.push_back(buildPort<Output>(child, scope));
    names.add(owner.outputs.back().name, at(child));
  } else if (kind == "token") {
    owner.tokens.push_back(buildToken(child));
    names.add(owner.tokens.back().name, at(child));
  } else {
    return false;
  }
  return true;
}

template <typename Owner>
void Builder::buildPorts(const xml::Element& e, const Scope& scope, Owner& owner, NameSet& names,
                         std::vector<xml::Element>* other) {
  for (const xml::Element& child : e.children()) {
    if (addPort(child, scope, owner, names)) continue;
    if (other) {
      other->push_back(child);
    } else {
      unexpectedChild(child, e.name());
    }
  }
}

Node Builder::buildNode(const xml::Element& e, const Scope& outer) {
  Scope scope = outer.enter(e);
  Node node;
  node.element = e;
  node.location = at(e);
  node.category = e.name();
  node.name = requireName(e);
  node.type = currentType(requireAttribute(e, "type", "a node declares its output type"));
  node.nodedef = e.attributeOr("nodedef", "");
  node.version = e.attributeOr("version", "");
  NameSet names(diagnostics_, "this node");
  buildPorts(e, scope, node, names, nullptr);
  return node;
}

NodeDef Builder::buildNodeDef(const xml::Element& e, const Scope& outer) {
  Scope scope = outer.enter(e);
  NodeDef def;
  def.element = e;
  def.location = at(e);
  def.name = qualified(scope, requireName(e));
  // A nodedef without `node` defines no node category: MaterialX reads it so (its test suite's
  // _options.mtlx keeps settings in one); nothing can instantiate it (NodeLibrary skips it).
  def.node = qualified(scope, e.attributeOr("node", ""));
  def.inherit = qualified(scope, e.attributeOr("inherit", ""));
  def.nodegroup = e.attributeOr("nodegroup", "");
  def.version = e.attributeOr("version", "");
  def.isDefaultVersion = parseBool(e, "isdefaultversion");
  def.target = e.attributeOr("target", "");
  NameSet names(diagnostics_, "this nodedef");
  buildPorts(e, scope, def, names, nullptr);
  if (legacy_) {
    // MaterialX 1.25's <shader shadertype= shaderprogram=> is a surface shader nodedef of the
    // category `shaderprogram`; up to 1.36 a nodedef gave its output type as a `type`
    // attribute, for an output named "out".
    def.legacyShader = e.findAttribute("shadertype") != nullptr;
    // MaterialX 1.22-1.23 named the shader's program `shadername` (1.24 made it `node`).
    if (e.name() == "shader") {
      def.node = qualified(scope, e.attributeOr("shaderprogram", e.attributeOr("shadername", e.attributeOr("node", ""))));
    }
    std::string_view type = def.legacyShader ? "surfaceshader" : currentType(e.attributeOr("type", ""));
    if (!type.empty() && type != "multioutput" && def.outputs.empty()) {
      Output out;
      out.name = "out";
      out.type = type;
      out.location = def.location;
      def.outputs.push_back(out);
    }
  }
  return def;
}

NodeGraph Builder::buildNodeGraph(const xml::Element& e, const Scope& outer) {
  Scope scope = outer.enter(e);
  NodeGraph graph;
  graph.element = e;
  graph.location = at(e);
  graph.name = qualified(scope, requireName(e));
  graph.nodedef = qualified(scope, e.attributeOr("nodedef", ""));
  NameSet names(diagnostics_, fmt::format("node graph '{}'", graph.name));
  std::vector<xml::Element> nodes;
  buildPorts(e, scope, graph, names, &nodes);
  for (const xml::Element& child : nodes) {
    std::string_view kind = child.name();
    if (kind == "nodegraph" || kind == "nodedef" || kind == "implementation" || kind == "typedef" || kind == "look" ||
        kind == "xi:include" || kind == "materialx") {
      diagnostics_.error(at(child), fmt::format("<{}> is not allowed inside a node graph", kind));
      continue;
    }
    graph.nodes.push_back(buildNode(child, scope));
    names.add(graph.nodes.back().name, at(child));
  }
  if (graph.outputs.empty()) {
    diagnostics_.warning(graph.location, fmt::format("node graph '{}' has no <output>", graph.name));
  }
  return graph;
}

LegacyMaterial Builder::buildLegacyMaterial(const xml::Element& e, const Scope& outer) {
  const Scope scope = outer.enter(e);
  LegacyMaterial material;
  material.name = requireName(e);
  material.location = at(e);
  NameSet names(diagnostics_, fmt::format("material '{}'", material.name));
  for (const xml::Element& child : e.children()) {
    const std::string_view kind = child.name();
    if (kind == "shaderref") {
      const Scope inner = scope.enter(child);
      ShaderRef ref;
      ref.name = requireName(child);
      ref.location = at(child);
      ref.node = qualified(inner, child.attributeOr("node", ""));
      ref.nodedef = qualified(inner, child.attributeOr("nodedef", ""));
      ref.type = child.attributeOr("type", child.findAttribute("shadertype") ? "surfaceshader" : "");
      ref.version = child.attributeOr("version", "");
      ref.target = child.attributeOr("target", "");
      names.add(ref.name, ref.location);
      NameSet bound(diagnostics_, fmt::format("shaderref '{}'", ref.name));
      for (const xml::Element& binding : child.children()) {
        const std::string_view bindingKind = binding.name();
        if (bindingKind == "bindinput" || bindingKind == "bindparam") {
          ref.bindings.push_back(buildPort<Input>(binding, inner));
          bound.add(ref.bindings.back().name, at(binding));
        } else if (bindingKind == "bindtoken") {
          ref.tokens.push_back(buildToken(binding));
          bound.add(ref.tokens.back().name, at(binding));
        } else {
          unexpectedChild(binding, "shaderref");
        }
      }
      material.shaderrefs.push_back(std::move(ref));
    } else if (kind == "override") {
      material.overrides.push_back(buildPort<Input>(child, scope));
    } else if (kind == "materialinherit") {
      diagnostics_.warning(at(child), fmt::format("material inheritance (<materialinherit>) is not upgraded: "
                                                  "material '{}' keeps only its own shader references",
                                                  material.name));
    } else {
      unexpectedChild(child, "material");
    }
  }
  return material;
}

void Builder::build() {
  xml::Element root = doc_.xml().root();
  doc_.location = at(root);
  if (root.name() != "materialx") {
    diagnostics_.error(at(root),
                       fmt::format("the root element is <{}>; a MaterialX document starts with <materialx>", root.name()));
    return;
  }
  doc_.version = root.attributeOr("version", "");
  doc_.colorspace = root.attributeOr("colorspace", "");
  doc_.fileprefix = root.attributeOr("fileprefix", "");
  const std::optional<Version> version = parseVersion(doc_.version);
  if (doc_.version.empty()) {
    diagnostics_.warning(at(root), "<materialx> has no version; reading it as MaterialX 1.39");
  } else if (!version || *version > Version{1, 39} || *version < Version{1, 22}) {
    diagnostics_.warning(valueAt(root, "version"),
                         fmt::format("MaterialX version {} is not one mxc knows (1.22 to 1.39); reading it as 1.39",
                                     doc_.version));
  }
  legacy_ = version && *version >= Version{1, 22} && *version < Version{1, 38};
  Scope scope = Scope().enter(root);
  NameSet names(diagnostics_, "the document");
  const std::vector<xml::Element> children = root.children();
  names.reserve(children.size());
  doc_.nodes.reserve(children.size());
  for (const xml::Element& e : children) {
    std::string_view kind = e.name();
    if (kind == "nodedef" || (legacy_ && kind == "shader")) {
      doc_.nodedefs.push_back(buildNodeDef(e, scope));
      names.add(doc_.nodedefs.back().name, at(e));
    } else if (legacy_ && kind == "material") {
      doc_.legacyMaterials.push_back(buildLegacyMaterial(e, scope));
      names.add(doc_.legacyMaterials.back().name, at(e));
    } else if (kind == "nodegraph" || (legacy_ && kind == "opgraph")) {
      doc_.nodegraphs.push_back(buildNodeGraph(e, scope));
      names.add(doc_.nodegraphs.back().name, at(e));
    } else if (kind == "implementation") {
      Implementation impl;
      impl.location = at(e);
      const Scope inner = scope.enter(e);
      impl.name = qualified(inner, requireName(e));
      impl.nodedef = qualified(inner, requireAttribute(e, "nodedef", "an implementation names the nodedef it implements"));
      impl.nodegraph = qualified(inner, e.attributeOr("nodegraph", ""));
      impl.file = e.attributeOr("file", "");
      impl.function = e.attributeOr("function", "");
      impl.target = e.attributeOr("target", "");
      impl.sourcecode = e.attributeOr("sourcecode", "");
      doc_.implementations.push_back(impl);
      names.add(impl.name, at(e));
    } else if (kind == "typedef") {
      TypeDef t{requireName(e), e.attributeOr("semantic", ""), e.attributeOr("context", ""), at(e), {}};
      NameSet members(diagnostics_, fmt::format("typedef '{}'", t.name));
      for (const xml::Element& child : e.children()) {
        if (child.name() != "member") {
          unexpectedChild(child, "typedef");
          continue;
        }
        TypeDef::Member m;
        m.location = at(child);
        m.name = requireName(child);
        m.type = requireAttribute(child, "type", "a struct member declares its type");
        m.valueString = child.attribute("value");
        members.add(m.name, m.location);
        t.members.push_back(m);
      }
      doc_.typedefs.push_back(std::move(t));
      names.add(t.name, at(e));
    } else if (kind == "geompropdef") {
      GeomPropDef g;
      g.location = at(e);
      g.name = requireName(e);
      g.type = requireAttribute(e, "type", "a geompropdef declares its type");
      g.geomprop = requireAttribute(e, "geomprop", "a geompropdef names the geometric property");
      g.space = e.attributeOr("space", "");
      g.index = e.attributeOr("index", "");
      doc_.geompropdefs.push_back(g);
      names.add(g.name, at(e));
    } else if (kind == "unitdef") {
      UnitDef u;
      u.location = at(e);
      u.name = requireName(e);
      u.unittype = requireAttribute(e, "unittype", "a unitdef names its unit type");
      for (const xml::Element& unit : e.children()) {
        if (unit.name() != "unit") {
          unexpectedChild(unit, "unitdef");
          continue;
        }
        ValueError error;
        auto scale = tryParseValue(ValueType::Float, unit.attributeOr("scale", "1"), &error);
        if (!scale) diagnostics_.error(valueAt(unit, "scale"), "invalid unit scale: " + error.message);
        u.units.push_back({requireName(unit), scale ? scale->as<float>() : 1.0f});
      }
      doc_.unitdefs.push_back(u);
      names.add(u.name, at(e));
    } else if (kind == "look") {
      Look look;
      look.location = at(e);
      look.name = requireName(e);
      for (const xml::Element& child : e.children()) {
        if (child.name() == "materialassign") {
          look.assigns.push_back({requireName(child), child.attributeOr("material", ""), child.attributeOr("geom", ""),
                                  child.attributeOr("collection", ""), at(child)});
        }
      }
      doc_.looks.push_back(look);
      names.add(look.name, at(e));
    } else if (kind == "xi:include") {
      auto href = e.attribute("href");
      if (!href || href->empty()) {
        diagnostics_.error(at(e), "<xi:include> has no 'href' attribute naming the file to include");
        continue;
      }
      doc_.includes.push_back({*href, valueAt(e, "href"), nullptr});
    } else if (isKeptElement(kind)) {
      doc_.otherElements.push_back(e);
    } else if (addPort(e, scope, doc_, names)) {
      // the document's own input, output or token (the document is a node graph too)
    } else if (kind == "parameter") {
      diagnostics_.error(at(e), "<parameter> is MaterialX 1.37 syntax, and belongs inside a node or nodedef");
    } else {
      doc_.nodes.push_back(buildNode(e, scope));
      names.add(doc_.nodes.back().name, at(e));
    }
  }
  doc_.link();
}

}  // namespace

std::unique_ptr<Document> buildDocument(xml::Document xml, Diagnostics& diagnostics) {
  auto document = std::make_unique<Document>(std::move(xml));
  Builder(*document, diagnostics).build();
  return document;
}

}  // namespace mxc::doc
