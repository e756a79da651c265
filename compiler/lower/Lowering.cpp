#include "compiler/lower/Lowering.h"

#include <fmt/format.h>

#include "compiler/lower/Context.h"

namespace mxc::lower {

namespace {

/// `--set` and `--param` must name inputs of the shading node.
void checkUserInputs(Context& c, const LoweringOptions& options, const std::string& material) {
  std::vector<std::string> names;
  for (const auto& o : options.overrides) names.push_back(o.first);
  names.insert(names.end(), options.parameters.begin(), options.parameters.end());
  for (const std::string& name : names) {
    if (!c.shaderNode) {
      c.error({}, fmt::format("--set/--param {}: material '{}' has no shading node to set it on", name, material));
    } else if (!c.shaderNode->findInput(name)) {
      c.error(c.shaderNode->node->location,
              fmt::format("--set/--param {}: <{}> has no input named '{}'", name, c.shaderNode->category(), name));
    }
  }
}

/// The shading node's inputs as the compilation sees them (ir::ShaderInput), after lowering.
void recordShaderInputs(const resolve::ResolvedNode& node, const LoweringOptions& options, ir::Material& material) {
  for (const resolve::ResolvedInput& in : node.inputs) {
    ir::ShaderInput out;
    out.name = in.name;
    out.location = in.location;
    const bool valued = in.source == resolve::InputSource::Value || in.source == resolve::InputSource::Default;
    out.source = in.source == resolve::InputSource::Value     ? ir::ShaderInput::Source::Document
                 : in.source == resolve::InputSource::Default ? ir::ShaderInput::Source::Default
                                                              : ir::ShaderInput::Source::Connected;
    if (valued && in.value) out.value = in.value->str();
    for (const auto& [name, text] : options.overrides) {
      if (name == in.name) {
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
  checkUserInputs(c, options, material.name);
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

}  // namespace mxc::lower
