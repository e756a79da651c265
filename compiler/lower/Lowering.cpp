#include "compiler/lower/Lowering.h"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compiler/lower/Context.h"

namespace mxc::lower {

namespace {

/// The shading node's inputs as the compilation sees them (ir::ShaderInput), after lowering.
void recordShaderInputs(const resolve::ResolvedNode& node, const LoweringOptions& options, ir::Material& material) {
  for (const resolve::ResolvedInput& in : node.inputs) {
    ir::ShaderInput out;
    out.name = in.name;
    out.type = in.type;
    out.location = in.location;
    const bool valued = in.source == resolve::InputSource::Value || in.source == resolve::InputSource::Default;
    out.source = in.source == resolve::InputSource::Value     ? ir::ShaderInput::Source::Document
                 : in.source == resolve::InputSource::Default ? ir::ShaderInput::Source::Default
                                                              : ir::ShaderInput::Source::Connected;
    if (valued && in.value) out.value = in.value->str();
    for (const auto& [name, text] : options.overrides) {
      if (name == in.name && doc::tryParseValue(doc::valueTypeOf(in.type), text)) {
        out.source = ir::ShaderInput::Source::Override;
        out.value = text;
      }
    }
    // A parameter as the lowering made it (Context::userInput decides): recorded after lowering.
    for (const ir::Parameter& p : material.parameters) {
      if (p.origin.input == in.name) out.source = ir::ShaderInput::Source::Parameter;
    }
    if (in.declaration && in.declaration->element.valid()) {
      const auto low = in.declaration->element.attribute("uimin");
      const auto high = in.declaration->element.attribute("uimax");
      if (low || high) out.range = fmt::format("{} to {}", low.value_or("-inf"), high.value_or("inf"));
    }
    material.shaderInputs.push_back(std::move(out));
  }
}

/// Lowers the closure feeding `input` in `env` as the whole material.
ir::Material lowerShader(const resolve::ResolvedDocument& document, const LoweringOptions& options,
                         Diagnostics& diagnostics, std::string name, const resolve::ResolvedNode* shader,
                         const resolve::ResolvedGraph* graph, const resolve::ResolvedInput* graphOutput) {
  ir::Material material;
  material.name = std::move(name);
  Context c(material, document, options, diagnostics);
  Closure root;
  c.shaderNode = shader;
  if (!shader && graphOutput && graphOutput->source == resolve::InputSource::Connection) {
    c.shaderNode = graphOutput->upstream.node;
  }
  if (shader) {
    material.shader = std::string(shader->category());
    material.origin = {shader->node->location, shader->name()};
    Env& env = shader->scope && shader->scope->graph ? c.graphEnv(*shader->scope) : c.topEnv();
    root = c.nodeClosure({shader, &env}, "out");
  } else if (graph && graphOutput) {
    material.shader = "surface";
    material.origin = {graphOutput->location, graphOutput->name};
    root = c.closure(*graphOutput, c.graphEnv(*graph));
    if (graphOutput->source == resolve::InputSource::Connection && graphOutput->upstream.node) {
      material.shader = std::string(graphOutput->upstream.node->category());
    }
  }
  if (root.kind == Closure::Kind::Scatter) {
    material.root = root.index;
  } else {
    material.root = material.leaf(ir::ScatterKind::Absorber, material.origin);
    if (!diagnostics.hasErrors()) {
      c.note(material.origin, "the shader has no BSDF: the surface is black");
    }
  }
  if (c.shaderNode) recordShaderInputs(*c.shaderNode, options, material);
  return material;
}

}  // namespace

std::vector<ir::Material> lowerDocument(const resolve::ResolvedDocument& document, const LoweringOptions& options,
                                        Diagnostics& diagnostics) {
  std::vector<ir::Material> materials;
  for (const resolve::ResolvedMaterial& m : document.materials) {
    if (findClosureRule(m.node->category())) {
      // A material node that is its own shader (LamaSurface: BSDFs in, a material out).
      materials.push_back(lowerShader(document, options, diagnostics, std::string(m.node->name()), m.node, nullptr,
                                      nullptr));
      continue;
    }
    for (const auto& shader : m.shaders) {
      if (shader.input != "surfaceshader") continue;  // displacement and volume shaders: not lowered
      materials.push_back(lowerShader(document, options, diagnostics, std::string(m.node->name()), shader.node,
                                      nullptr, nullptr));
    }
  }
  if (!document.materials.empty()) return materials;
  // No material: every surface shader a document-level graph outputs (pbrlib test documents),
  // then every document-level surface shader node.
  for (const auto& g : document.graphs) {
    if (g->implements) continue;
    for (const resolve::ResolvedInput& out : g->outputs) {
      if (out.type != "surfaceshader") continue;
      materials.push_back(lowerShader(document, options, diagnostics, fmt::format("{}/{}", g->name(), out.name),
                                      nullptr, g.get(), &out));
    }
  }
  for (const auto& node : document.top.nodes) {
    if (!node->signature || node->signature->outputType() != "surfaceshader") continue;
    bool consumed = false;
    for (const auto& other : document.top.nodes) {
      for (const resolve::ResolvedInput& in : other->inputs) consumed = consumed || in.upstream.node == node.get();
    }
    if (consumed) continue;
    materials.push_back(lowerShader(document, options, diagnostics, std::string(node->name()), node.get(), nullptr, nullptr));
  }
  return materials;
}

namespace {

/// The type of the input `name` names in `m` (its shading node's, else a graph interface input's:
/// GRAPH.INPUT, or INPUT), or empty when it names none.
std::string_view typeOfUserInput(const ir::Material& m, const std::string& name) {
  if (const ir::ShaderInput* in = m.shaderInput(name)) return in->type;
  for (const ir::GraphInput& g : m.graphInputs) {
    if (g.qualified == name || g.name == name) return g.type;
  }
  return {};
}

}  // namespace

void checkUserInputs(const std::vector<ir::Material>& materials, const LoweringOptions& options,
                     Diagnostics& diagnostics) {
  if (materials.empty()) return;
  std::vector<std::pair<std::string, std::string>> asked = options.overrides;  // (name, value); --param has none
  for (const std::string& p : options.parameters) asked.emplace_back(p, std::string());
  std::vector<std::string> done;
  for (size_t k = 0; k < asked.size(); ++k) {
    const auto& [name, text] = asked[k];
    const bool isSet = k < options.overrides.size();
    const std::string flag = isSet ? fmt::format("--set {}={}", name, text) : fmt::format("--param {}", name);
    if (std::find(done.begin(), done.end(), flag) != done.end()) continue;  // said once
    done.push_back(flag);
    std::vector<const ir::Material*> with, without;
    for (const ir::Material& m : materials) (typeOfUserInput(m, name).empty() ? without : with).push_back(&m);
    if (with.empty()) {
      if (materials.size() == 1) {
        const ir::Material& m = materials.front();
        if (m.shaderInputs.empty()) {
          diagnostics.error({}, fmt::format("{}: material '{}' has no shading node to set it on", flag, m.name));
        } else {
          std::string graphs;
          for (const ir::GraphInput& g : m.graphInputs) graphs += (graphs.empty() ? "" : ", ") + g.qualified;
          diagnostics.error(m.origin.location,
                            fmt::format("{}: <{}> has no input named '{}'{}", flag, m.shader, name,
                                        graphs.empty() ? std::string() : fmt::format(", nor has a graph it reads (graph inputs: {})", graphs)));
        }
      } else {
        std::vector<std::string> which;
        for (const ir::Material& m : materials) which.push_back(fmt::format("{} (<{}>)", m.name, m.shader));
        diagnostics.error({}, fmt::format("{}: no material's shading node has an input named '{}': {}", flag, name,
                                          fmt::join(which, ", ")));
      }
      continue;
    }
    if (isSet) {
      // The value is checked against each type the input has among the materials (one, as a rule).
      bool bad = false;
      for (const ir::Material* m : with) {
        const std::string_view type = typeOfUserInput(*m, name);
        doc::ValueError why;
        if (!bad && !doc::tryParseValue(doc::valueTypeOf(type), text, &why)) {
          // The parser's reason, when it says more than that ("expected 3 components, found 2").
          const bool more = why.message.find(text) == std::string::npos || text.empty();
          diagnostics.error({}, fmt::format("{}: '{}' is not a {}{}", flag, text, type,
                                            more ? fmt::format(" ({})", why.message) : std::string()));
          bad = true;
        }
      }
      if (bad) continue;
    }
    if (!without.empty()) {
      std::vector<std::string> applied, skipped;
      for (const ir::Material* m : with) applied.push_back(m->name);
      for (const ir::Material* m : without) skipped.push_back(fmt::format("{} (<{}>)", m->name, m->shader));
      diagnostics.note({}, fmt::format("{} applies to {}; not to {}, whose shading node has no input '{}'", flag,
                                       fmt::join(applied, ", "), fmt::join(skipped, ", "), name));
    }
  }
}

}  // namespace mxc::lower
