// Upgrading MaterialX 1.22-1.37 documents to the 1.38 form (Upgrade.h lists the rules). The
// rules are MaterialX's (its Version.cpp is the description of record); the code is ours, on our
// document model: the builder has already read the legacy elements (LegacyMaterial, ShaderRef,
// NodeDef::legacyShader, <parameter> as <input>, old type names), and this file rewrites them.

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "compiler/document/Upgrade.h"
#include "compiler/document/UpgradeScope.h"

namespace mxc::doc {

namespace {

/// The document's nodedef a shaderref binds, as MaterialX finds it: the `nodedef` it names, else
/// one of its `node` category (of its `type`, when given), else (1.25, where a shaderref named
/// its <shader> by name alone) the nodedef of the shaderref's own name. Null when the shader is
/// defined outside the document (a library's standard_surface): the shaderref's `node` and
/// `type` then say all that is needed.
const NodeDef* shaderNodeDef(const Document& doc, const ShaderRef& ref) {
  if (!ref.nodedef.empty()) return doc.findNodeDef(ref.nodedef);
  if (!ref.node.empty()) {
    for (const NodeDef& def : doc.nodedefs) {
      if (def.node != ref.node) continue;
      if (ref.type.empty() || (!def.outputs.empty() && def.outputs.front().type == ref.type)) return &def;
    }
    return nullptr;
  }
  return doc.findNodeDef(ref.name);
}

/// The shader node's inputs from 1.35 <override>s: an override names an input of the shader by
/// that input's `publicname`.
void applyOverrides(const LegacyMaterial& material, const NodeDef& def, Node& shader) {
  for (const Input& override : material.overrides) {
    for (const Input& declared : def.inputs) {
      if (!declared.element.valid() || declared.element.attributeOr("publicname", "") != override.name) continue;
      if (shader.findInput(declared.name)) continue;  // a binding of the same input wins
      Input bound = override;
      bound.name = declared.name;
      if (bound.type != declared.type) {
        bound.type = declared.type;
        if (bound.valueString) bound.value = tryParseValue(valueTypeOf(bound.type), *bound.valueString);
      }
      shader.inputs.push_back(bound);
    }
  }
}

/// MaterialX 1.22-1.26 connected a shader's input to a graph output on the <shader> itself:
/// `graphname` (1.25: `opgraph`) names the graph and `graphoutput` its output. MaterialX's 1.34
/// upgrade moves each to a binding of every shaderref of that shader; a binding the shaderref
/// makes itself wins.
void bindGraphOutputs(const NodeDef& def, Node& shader) {
  for (const Input& declared : def.inputs) {
    if (!declared.element.valid()) continue;
    const std::string_view graph = declared.element.attributeOr("graphname", declared.element.attributeOr("opgraph", ""));
    const std::string_view output = declared.element.attributeOr("graphoutput", "");
    if (graph.empty() || output.empty() || shader.findInput(declared.name)) continue;
    Input bound;
    bound.name = declared.name;
    bound.type = declared.type;
    bound.nodegraph = graph;
    bound.output = output;
    bound.location = declared.location;
    shader.inputs.push_back(bound);
  }
}

// MaterialX 1.38 replaced the <material> element by material nodes: each <shaderref> becomes a
// shader node (its bindings become inputs), and a surfacematerial node of the material's name
// connects them, one input per shader type.
void convertMaterials(Document& doc, Diagnostics& diagnostics) {
  std::set<std::string, std::less<>> taken;
  for (const Node& n : doc.nodes) taken.emplace(n.name);
  for (const NodeGraph& g : doc.nodegraphs) taken.emplace(g.name);
  for (const NodeDef& d : doc.nodedefs) {
    if (!d.legacyShader) taken.emplace(d.name);  // removed below, so its name is free
  }
  for (const LegacyMaterial& m : doc.legacyMaterials) taken.emplace(m.name);
  auto fresh = [&](std::string_view base) {
    std::string name(base);
    for (int i = 2; taken.count(name); ++i) name = fmt::format("{}{}", base, i);
    taken.insert(name);
    return doc.own(name);
  };

  std::vector<Node> added;
  for (const LegacyMaterial& material : doc.legacyMaterials) {
    std::optional<Node> materialNode;
    for (const ShaderRef& ref : material.shaderrefs) {
      const NodeDef* def = shaderNodeDef(doc, ref);
      const std::string_view category = def ? def->node : ref.node;
      if (category.empty()) {
        diagnostics.error(ref.location, fmt::format("cannot upgrade shaderref '{}' of material '{}': it names no "
                                                    "shader (no 'node' or 'nodedef' attribute, and no nodedef of "
                                                    "its name in the document)",
                                                    ref.name, material.name));
        continue;
      }
      Node shader;
      shader.category = category;
      shader.name = fresh(ref.name);
      shader.type = def && !def->outputs.empty() ? def->outputs.front().type
                    : !ref.type.empty()          ? ref.type
                                                 : std::string_view("surfaceshader");
      // A legacy shader nodedef is removed below, so the node must not name it.
      shader.nodedef = def && def->legacyShader ? std::string_view() : ref.nodedef;
      shader.version = ref.version;
      shader.location = ref.location;
      shader.inputs = ref.bindings;
      shader.tokens = ref.tokens;
      if (def) applyOverrides(material, *def, shader);
      if (def) bindGraphOutputs(*def, shader);

      if (!materialNode) {
        materialNode.emplace();
        materialNode->category = "surfacematerial";
        materialNode->name = material.name;
        materialNode->type = "material";
        materialNode->location = material.location;
      }
      if (!materialNode->findInput(shader.type)) {
        Input connection;
        connection.name = shader.type;
        connection.type = shader.type;
        connection.nodename = shader.name;
        connection.location = ref.location;
        materialNode->inputs.push_back(connection);
      }
      doc.upgradeNotes.push_back(
          fmt::format("material '{}': shaderref '{}' became the {} node '{}'", material.name, ref.name, category, shader.name));
      added.push_back(std::move(shader));
    }
    if (materialNode) {
      added.push_back(std::move(*materialNode));
    } else {
      diagnostics.warning(material.location,
                          fmt::format("material '{}' binds no shader; it is dropped by the upgrade", material.name));
    }
  }
  for (Node& n : added) doc.nodes.push_back(std::move(n));
  doc.legacyMaterials.clear();
  // MaterialX 1.37 removed the shader nodedefs of 1.36 (`shadertype`); the nodes above stand for
  // the materials that used them.
  std::erase_if(doc.nodedefs, [](const NodeDef& d) { return d.legacyShader; });
}

// MaterialX 1.37 gave several nodes new names or sized forms.
int renameNodesOf137(ScopeNodes scope) {
  int edits = 0;
  std::set<std::string_view> removed;
  for (Node& n : *scope.nodes) {
    const std::string_view category = n.category;
    if (category == "invert" && (n.type == "matrix33" || n.type == "matrix44")) {
      n.category = "invertmatrix";
    } else if (category == "rotate") {
      n.category = n.type == "vector2" ? "rotate2d" : "rotate3d";
    } else if (category == "compare") {
      // compare(intest, cutoff, in1, in2) chose in1 when intest <= cutoff; ifgreatereq(value1,
      // value2, in1, in2) chooses in1 when value1 >= value2, so in1 and in2 trade places.
      n.category = "ifgreatereq";
      Input* in1 = n.findInput("in1");
      Input* in2 = n.findInput("in2");
      for (Input& in : n.inputs) {
        if (in.name == "intest") in.name = "value1";
        if (in.name == "cutoff") in.name = "value2";
      }
      if (in1 && in2) std::swap(in1->name, in2->name);
    } else if (category == "transformpoint" || category == "transformvector" || category == "transformnormal") {
      if (!n.findInput("fromspace") && !n.findInput("tospace")) n.category = "transformmatrix";
    } else if (category == "combine") {
      n.category = n.findInput("in4") ? "combine4" : n.findInput("in3") ? "combine3" : "combine2";
    } else if (category == "separate") {
      const Input* in = n.findInput("in");
      const std::string_view type = in ? in->type : std::string_view();
      n.category = (type == "vector4" || type == "color4")   ? "separate4"
                   : (type == "vector3" || type == "color3") ? "separate3"
                                                             : "separate2";
    } else if (category == "geomattrvalue") {
      n.category = "geompropvalue";
      if (n.element.valid() && !n.findInput("geomprop")) {
        if (auto attribute = n.element.attribute("attrname")) {
          Input geomprop;
          geomprop.name = "geomprop";
          geomprop.type = "string";
          geomprop.valueString = *attribute;
          geomprop.value = Value(ValueType::String, std::string(*attribute));
          geomprop.location = n.attributeLocation("attrname");
          n.inputs.push_back(geomprop);
        }
      }
    } else if (category == "backdrop") {
      removed.insert(n.name);  // a layout note, an element of its own since 1.37
    } else {
      continue;
    }
    ++edits;
  }
  std::erase_if(*scope.nodes, [&](const Node& n) { return removed.count(n.name) > 0; });
  return edits;
}

/// A 1.37 BSDF node with a `base` input layered itself over that base; 1.38 writes
/// layer(top = node, base = base). The node takes the name `<name>__layer_top` and the layer
/// takes its name, so every connection to the old node now reaches the layer.
void layerOverBase(Node& node, AddedNodes& added) {
  auto base = std::find_if(node.inputs.begin(), node.inputs.end(), [](const Input& in) { return in.name == "base"; });
  if (base == node.inputs.end()) return;
  if (base->isConnected()) {
    Node layer;
    layer.category = "layer";
    layer.name = node.name;
    layer.type = "BSDF";
    layer.location = node.location;
    node.name = added.doc.own(added.scope.uniqueName(std::string(node.name) + "__layer_top"));
    Input top;
    top.name = "top";
    top.type = "BSDF";
    top.nodename = node.name;
    top.location = node.location;
    Input under = *base;
    under.element = {};
    layer.inputs = {top, under};
    added.nodes.push_back(std::move(layer));
  }
  node.inputs.erase(base);
}

// MaterialX 1.38 renamed the pbrlib BSDFs (*_brdf, *_btdf -> *_bsdf), made layering a node of
// its own, gave conductor_bsdf a physical (ior, extinction) parameterisation, and swapped
// atan2's inputs.
int upgradeBsdfsOf138(Document& doc, ScopeNodes scope) {
  int edits = 0;
  AddedNodes added{doc, scope, {}};
  for (size_t i = 0; i < scope.nodes->size(); ++i) {
    Node& n = (*scope.nodes)[i];
    const std::string_view category = n.category;
    if (category == "dielectric_brdf" || category == "generalized_schlick_brdf" || category == "sheen_brdf" ||
        category == "thin_film_brdf") {
      n.category = category == "dielectric_brdf"            ? "dielectric_bsdf"
                   : category == "generalized_schlick_brdf" ? "generalized_schlick_bsdf"
                   : category == "sheen_brdf"               ? "sheen_bsdf"
                                                            : "thin_film_bsdf";
      layerOverBase(n, added);
    } else if (category == "dielectric_btdf") {
      n.category = "dielectric_bsdf";
      std::erase_if(n.inputs, [](const Input& in) { return in.name == "interior"; });
      Input mode;
      mode.name = "scatter_mode";
      mode.type = "string";
      mode.valueString = "T";
      mode.value = Value(ValueType::String, std::string("T"));
      mode.location = n.location;
      n.inputs.push_back(mode);
    } else if (category == "conductor_brdf") {
      // The artistic (reflectivity, edge_color) inputs move to an artistic_ior node (Gulbrandsen
      // 2014) whose ior and extinction outputs feed the conductor.
      n.category = "conductor_bsdf";
      const size_t k = added.add("artistic_ior", "multioutput", std::string(n.name) + "__artistic_ior", n);
      Node& artistic = added.nodes[k];
      for (std::string_view output : {"ior", "extinction"}) {
        Output out;
        out.name = output;
        out.type = "color3";
        out.location = n.location;
        artistic.outputs.push_back(out);
      }
      for (Input& in : n.inputs) {
        if (in.name == "reflectivity" || in.name == "edge_color") artistic.inputs.push_back(in);
      }
      std::erase_if(n.inputs, [](const Input& in) { return in.name == "reflectivity" || in.name == "edge_color"; });
      for (std::string_view output : {"ior", "extinction"}) {
        Input in;
        in.name = output;
        in.type = "color3";
        in.nodename = artistic.name;
        in.output = output;
        in.location = n.location;
        n.inputs.push_back(in);
      }
    } else if (category == "diffuse_brdf") {
      n.category = "oren_nayar_diffuse_bsdf";
    } else if (category == "burley_diffuse_brdf") {
      n.category = "burley_diffuse_bsdf";
    } else if (category == "diffuse_btdf") {
      n.category = "translucent_bsdf";
    } else if (category == "subsurface_brdf") {
      n.category = "subsurface_bsdf";
    } else if (category == "atan2") {
      // 1.37's atan2(in1, in2) is 1.38's atan2(in2, in1) (upgradeTo139 then names them iny, inx).
      Input* in1 = n.findInput("in1");
      Input* in2 = n.findInput("in2");
      if (in1 && in2) {
        std::swap(in1->name, in2->name);
      } else if (in1) {
        in1->name = "in2";
      } else if (in2) {
        in2->name = "in1";
      }
    } else {
      continue;
    }
    ++edits;
  }
  added.commit();

  // artistic_ior's outputs became color3 in 1.38; an input that took them as vector3 now goes
  // through a convert node (one per output, shared by its readers).
  AddedNodes converts{doc, scope, {}};
  std::map<std::pair<std::string_view, std::string_view>, std::string_view> convertOf;
  for (Node& n : *scope.nodes) {
    if (n.category == "artistic_ior") {
      for (Output& out : n.outputs) out.type = "color3";
    }
  }
  scope.forEachPort([&](Port& port) {
    if (port.type != "vector3" || (port.output != "ior" && port.output != "extinction")) return;
    const Node* source = scope.find(port.nodename);
    if (!source || source->category != "artistic_ior") return;
    if (auto it = convertOf.find({port.nodename, port.output}); it != convertOf.end()) {
      port.nodename = it->second;
      port.output = {};
      return;
    }
    const size_t k = converts.add("convert", "vector3", fmt::format("{}__convert_{}", port.nodename, port.output),
                                  port.location);
    Input in;
    in.name = "in";
    in.type = "color3";
    in.nodename = port.nodename;
    in.output = port.output;
    in.location = port.location;
    converts.nodes[k].inputs.push_back(in);
    convertOf[{port.nodename, port.output}] = converts.nodes[k].name;
    port.nodename = converts.nodes[k].name;
    port.output = {};
  });
  converts.commit();
  return edits;
}

// MaterialX 1.22-1.26 forms inside a scope: a node input of type `opgraphnode` (the builder
// made it a connection) takes the connected node's type, or color3 when there is no such node
// (MaterialX's 1.34 upgrade); constant's input `color` is `value` since 1.26.
int upgradeNodesOf126(ScopeNodes scope, Version version) {
  int edits = 0;
  for (Node& n : *scope.nodes) {
    for (Input& in : n.inputs) {
      if (in.type == "opgraphnode") {
        const Node* source = scope.find(in.nodename);
        in.type = source && !source->type.empty() ? source->type : std::string_view("color3");
        ++edits;
      }
      if (version < Version{1, 26} && n.category == "constant" && in.name == "color") in.name = "value", ++edits;
    }
  }
  return edits;
}

/// A filename as 1.36 writes it: MaterialX 1.35's %UDIM and %UVTILE are <UDIM> and <UVTILE>.
int renameFilenameTokens(Document& doc, Port& port) {
  if (port.type != "filename" || !port.valueString) return 0;
  std::string text(*port.valueString);
  bool changed = false;
  for (auto [from, to] : {std::pair<std::string_view, std::string_view>{"%UDIM", "<UDIM>"}, {"%UVTILE", "<UVTILE>"}}) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
      changed = true;
    }
  }
  if (!changed) return 0;
  port.valueString = doc.own(text);
  port.value = Value(ValueType::Filename, text);
  return 1;
}

}  // namespace

void upgradeTo138(Document& doc, Diagnostics& diagnostics) {
  const Version version = doc.versionNumber();
  if (version >= Version{1, 38}) return;
  doc.upgradeNotes.push_back(fmt::format("upgraded from MaterialX {}", doc.version));
  convertMaterials(doc, diagnostics);
  int renamed = 0;
  int forms126 = 0;
  int bsdfs = 0;
  int filenames = 0;
  for (ScopeNodes scope : scopesOf(doc)) {
    if (version < Version{1, 34}) forms126 += upgradeNodesOf126(scope, version);
    if (version < Version{1, 37}) renamed += renameNodesOf137(scope);
    bsdfs += upgradeBsdfsOf138(doc, scope);
    if (version < Version{1, 36}) scope.forEachPort([&](Port& port) { filenames += renameFilenameTokens(doc, port); });
  }
  if (forms126) {
    doc.upgradeNotes.push_back(
        fmt::format("{} 1.26 forms upgraded (opgraphnode inputs typed, constant color named value)", forms126));
  }
  if (renamed) doc.upgradeNotes.push_back(fmt::format("{} nodes renamed to their 1.37 categories", renamed));
  if (bsdfs) doc.upgradeNotes.push_back(fmt::format("{} nodes upgraded to the 1.38 BSDFs and atan2", bsdfs));
  if (filenames) doc.upgradeNotes.push_back(fmt::format("{} filenames use <UDIM>/<UVTILE>", filenames));
  doc.link();
}

}  // namespace mxc::doc
