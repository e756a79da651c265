#include "compiler/document/Upgrade.h"

#include <algorithm>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "compiler/document/UpgradeScope.h"

namespace mxc::doc {

namespace {

// MaterialX 1.39 renamed the inputs of atan2 from in1/in2 to iny/inx (same order: y, then x).
int renameAtan2Inputs(ScopeNodes scope) {
  int edits = 0;
  for (Node& n : *scope.nodes) {
    if (n.category != "atan2") continue;
    for (Input& in : n.inputs) {
      if (in.name == "in1") in.name = "iny", ++edits;
      if (in.name == "in2") in.name = "inx", ++edits;
    }
  }
  return edits;
}

// MaterialX 1.39 made subsurface_bsdf's radius a color3 (it was a vector3): a vector3 value is
// reinterpreted, a vector3 connection goes through a new convert node.
int convertSubsurfaceRadius(Document& doc, ScopeNodes scope) {
  int edits = 0;
  AddedNodes added{doc, scope, {}};
  for (Node& n : *scope.nodes) {
    if (n.category != "subsurface_bsdf") continue;
    Input* radius = n.findInput("radius");
    if (!radius || radius->type != "vector3") continue;
    radius->type = "color3";
    ++edits;
    if (radius->value) {
      radius->value = Value(ValueType::Color3, radius->value->as<glm::vec3>());
      continue;
    }
    if (!radius->isConnected()) continue;
    // The convert sits where the radius was written (its messages point at that input).
    const size_t convert = added.add("convert", "color3", std::string(n.name) + "_radius_color3", radius->location);
    added.nodes[convert].inputs.push_back(added.moved(radius, "in", "vector3", "", radius->location));
    radius->nodename = added.nodes[convert].name;
    radius->nodegraph = {};
    radius->interfacename = {};
    radius->output = {};
  }
  added.commit();
  return edits;
}

bool isBsdfCombinator(std::string_view category) {
  return category == "layer" || category == "mix" || category == "add" || category == "multiply";
}

bool takesThinFilm(std::string_view category) {
  return category == "dielectric_bsdf" || category == "conductor_bsdf" || category == "generalized_schlick_bsdf";
}

// MaterialX 1.38 wrote thin film as layer(top = thin_film_bsdf, base = B). In 1.39 the film is a
// property of the Fresnel of the dielectric, conductor and generalized-Schlick BSDFs under it
// (thinfilm_thickness, thinfilm_ior inputs), which is also how our IR models it (the seed
// commentary, section 4.2). The layer is replaced by B and the film moves onto B's BSDFs.
int foldThinFilmLayers(Document& doc, ScopeNodes scope, Diagnostics& diagnostics) {
  int edits = 0;
  std::set<std::string_view> removed;
  for (Node& layer : *scope.nodes) {
    if (layer.category != "layer") continue;
    Input* top = layer.findInput("top");
    Input* base = layer.findInput("base");
    if (!top || top->nodename.empty()) continue;
    Node* film = scope.find(top->nodename);
    if (!film || film->category != "thin_film_bsdf") continue;
    if (!base || base->nodename.empty()) {
      diagnostics.error(layer.location, fmt::format("cannot upgrade the 1.38 thin-film layer '{}': its base is not "
                                                    "a node of the same graph",
                                                    layer.name));
      continue;
    }
    // The film's inputs, with the 1.38 defaults of thin_film_bsdf (550 nm, IOR 1.5).
    Input thickness;
    Input ior;
    if (const Input* t = film->findInput("thickness")) thickness = *t;
    else thickness.value = Value(ValueType::Float, 550.0f), thickness.valueString = "550";
    if (const Input* i = film->findInput("ior")) ior = *i;
    else ior.value = Value(ValueType::Float, 1.5f), ior.valueString = "1.5";
    thickness.name = "thinfilm_thickness";
    ior.name = "thinfilm_ior";
    thickness.type = ior.type = "float";
    thickness.element = ior.element = {};
    if (!thickness.location.valid()) thickness.location = film->location;
    if (!ior.location.valid()) ior.location = film->location;

    // Every thin-film-capable BSDF reachable from the base through BSDF combinators.
    std::vector<std::string_view> pending{base->nodename};
    std::set<std::string_view> visited;
    while (!pending.empty()) {
      std::string_view name = pending.back();
      pending.pop_back();
      if (!visited.insert(name).second) continue;
      Node* n = scope.find(name);
      if (!n) continue;
      if (takesThinFilm(n->category)) {
        if (!n->findInput("thinfilm_thickness")) n->inputs.push_back(thickness);
        if (!n->findInput("thinfilm_ior")) n->inputs.push_back(ior);
      } else if (isBsdfCombinator(n->category)) {
        for (const Input& in : n->inputs) {
          if ((in.type == "BSDF") && !in.nodename.empty()) pending.push_back(in.nodename);
        }
      }
    }
    const std::string_view baseName = base->nodename;
    const std::string_view baseOutput = base->output;
    scope.forEachPort([&](Port& port) {
      if (port.nodename == layer.name) {
        port.nodename = baseName;
        port.output = baseOutput;
      }
    });
    removed.insert(layer.name);
    removed.insert(film->name);
    doc.upgradeNotes.push_back(fmt::format("thin-film layer '{}' folded into the BSDFs under '{}'", layer.name, baseName));
    ++edits;
  }
  if (!removed.empty()) {
    std::erase_if(*scope.nodes, [&](const Node& n) { return removed.count(n.name) > 0; });
  }
  return edits;
}

// MaterialX 1.39 removed the swizzle node. A connected swizzle becomes a `dot` (the identity)
// whose input takes the channels of the connected value, the 1.38 `channels` form the resolver
// already applies; a swizzle of a value (or of nothing) becomes a `constant` of the swizzled
// components, as MaterialX's upgrade does: channel r/x, g/y, b/z, a/w picks a component, 0 and
// 1 are constants, and a missing or unknown channel repeats the first component.
int convertSwizzleNodes(Document& doc, ScopeNodes scope) {
  int edits = 0;
  for (Node& n : *scope.nodes) {
    if (n.category != "swizzle") continue;
    Input* in = n.findInput("in");
    const Input* channelsInput = n.findInput("channels");
    const std::string_view channels = channelsInput && channelsInput->valueString ? *channelsInput->valueString : "";
    const ValueType destination = valueTypeOf(n.type);
    ++edits;
    if (in && in->isConnected()) {
      n.category = "dot";
      in->type = n.type;
      in->channels = channels;
      std::erase_if(n.inputs, [](const Input& i) { return i.name == "channels"; });
      continue;
    }
    std::vector<float> source{0.0f};
    if (in && in->value && !in->value->components().empty()) source = in->value->components();
    std::string text;
    for (int k = 0; k < std::max(componentCount(destination), 1); ++k) {
      const char c = k < static_cast<int>(channels.size()) ? channels[static_cast<size_t>(k)] : '?';
      const std::string_view names = "rgbaxyzw";
      const size_t at = names.find(c);
      float v = source[0];
      if (c == '0' || c == '1') v = c == '0' ? 0.0f : 1.0f;
      else if (at != std::string_view::npos && at % 4 < source.size()) v = source[at % 4];
      text += (k ? ", " : "") + formatFloat(v);
    }
    Input value;
    value.name = "value";
    value.type = n.type;
    value.location = n.location;
    value.valueString = doc.own(text);
    value.value = tryParseValue(destination, *value.valueString);
    value.valueLocation = n.location;
    n.category = "constant";
    n.inputs.clear();
    n.inputs.push_back(value);
  }
  // The nodedef a swizzle named (ND_swizzle_color3_color3, ...) is gone: the node it became is
  // matched by its signature.
  for (Node& n : *scope.nodes) {
    if (n.nodedef.starts_with("ND_swizzle_")) n.nodedef = {};
  }
  return edits;
}

// MaterialX 1.39 changed normalmap (its specification's "normalmap" and the 1.39 changes): the
// `space` input is gone, the nodedef ND_normalmap became ND_normalmap_float (a vector2 scale
// has its own), and the bitangent is an input. An object-space normal map, a remapped normal
// with no frame, becomes normalize(in * 2 - 1); a tangent-space one keeps its node, and where
// the 1.38 document gave a normal or a tangent without a bitangent, the bitangent 1.38 derived,
// normalize(cross(normal, tangent)), is given explicitly.
int upgradeNormalMaps(Document& doc, ScopeNodes scope) {
  int edits = 0;
  AddedNodes added{doc, scope, {}};
  for (Node& n : *scope.nodes) {
    if (n.category != "normalmap") continue;
    if (n.nodedef == "ND_normalmap") n.nodedef = "ND_normalmap_float", ++edits;
    const Input* space = n.findInput("space");
    const bool objectSpace = space && space->valueString && *space->valueString == "object";
    const std::string base(n.name);
    if (objectSpace) {
      const size_t scaled = added.add("multiply", "vector3", base + "_decode", n);
      added.nodes[scaled].inputs.push_back(added.moved(n.findInput("in"), "in1", "vector3", "0.5, 0.5, 1", n.location));
      added.nodes[scaled].inputs.push_back(added.moved(nullptr, "in2", "float", "2", n.location));
      const size_t centred = added.add("subtract", "vector3", base + "_centre", n);
      added.nodes[centred].inputs.push_back(added.connection("in1", "vector3", scaled));
      added.nodes[centred].inputs.push_back(added.moved(nullptr, "in2", "float", "1", n.location));
      n.category = "normalize";
      if (!n.nodedef.empty()) n.nodedef = "ND_normalize_vector3";
      n.inputs.clear();
      n.inputs.push_back(added.connection("in", "vector3", centred));
      ++edits;
      continue;
    }
    if (space) std::erase_if(n.inputs, [](const Input& i) { return i.name == "space"; }), ++edits;
    const Input* normal = n.findInput("normal");
    const Input* tangent = n.findInput("tangent");
    if ((normal || tangent) && !n.findInput("bitangent")) {
      // The one of the two not given is the geometry's own (the nodedef's defaultgeomprop).
      const size_t cross = added.add("crossproduct", "vector3", base + "_cross", n);
      for (auto [port, name, geomprop] : {std::tuple{normal, "in1", "normal"}, std::tuple{tangent, "in2", "tangent"}}) {
        if (port) {
          Input in = added.moved(port, name, "vector3", "", n.location);
          added.nodes[cross].inputs.push_back(in);
          continue;
        }
        const size_t frame = added.add(geomprop, "vector3", base + "_" + geomprop, n);
        added.nodes[frame].inputs.push_back(added.moved(nullptr, "space", "string", "world", n.location));
        Input in = added.connection(name, "vector3", frame);
        added.nodes[cross].inputs.push_back(in);
      }
      const size_t unit = added.add("normalize", "vector3", base + "_bitangent", n);
      added.nodes[unit].inputs.push_back(added.connection("in", "vector3", cross));
      n.inputs.push_back(added.connection("bitangent", "vector3", unit));
      ++edits;
    }
  }
  added.commit();
  return edits;
}

// MaterialX 1.39 gave switch 10 inputs where 1.38 had 5, and a constant `which` of 5 or more,
// out of range in 1.38, chose in1 there: it is set to 0 so that it still does.
int upgradeSwitchSelectors(Document& doc, ScopeNodes scope) {
  int edits = 0;
  for (Node& n : *scope.nodes) {
    if (n.category != "switch") continue;
    Input* which = n.findInput("which");
    if (!which || which->isConnected() || !which->value) continue;
    const ValueType type = which->value->type();
    const bool outOfRange = (type == ValueType::Integer && which->value->as<int32_t>() >= 5) ||
                            (type == ValueType::Float && which->value->as<float>() >= 5.0f);
    if (!outOfRange) continue;
    which->valueString = doc.own("0");
    which->value = tryParseValue(type, "0");
    ++edits;
  }
  return edits;
}

}  // namespace

void upgradeTo139(Document& doc, Diagnostics& diagnostics) {
  if (doc.versionNumber() >= Version{1, 39}) return;
  int atan2 = 0;
  int radius = 0;
  int swizzles = 0;
  int normalmaps = 0;
  int switches = 0;
  for (ScopeNodes scope : scopesOf(doc)) {
    swizzles += convertSwizzleNodes(doc, scope);
    normalmaps += upgradeNormalMaps(doc, scope);
    switches += upgradeSwitchSelectors(doc, scope);
    atan2 += renameAtan2Inputs(scope);
    radius += convertSubsurfaceRadius(doc, scope);
    foldThinFilmLayers(doc, scope, diagnostics);
  }
  if (atan2) doc.upgradeNotes.push_back(fmt::format("{} atan2 inputs renamed to iny/inx", atan2));
  if (radius) doc.upgradeNotes.push_back(fmt::format("{} subsurface_bsdf radius inputs made color3", radius));
  if (swizzles) doc.upgradeNotes.push_back(fmt::format("{} swizzle nodes made dot (with channels) or constant nodes", swizzles));
  if (normalmaps) doc.upgradeNotes.push_back(fmt::format("{} normalmap changes (space, bitangent, ND_normalmap_float)", normalmaps));
  if (switches) doc.upgradeNotes.push_back(fmt::format("{} switch selectors of 5 or more set to 0", switches));
  doc.link();
}

}  // namespace mxc::doc
