#pragma once
// The shaders the SPIR-V stage's corpus checks compile (SourceTrimTest, InstructionIdsTest).

#include <string>
#include <utility>
#include <vector>

#include "compiler/driver/Compiler.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "support/TestSupport.h"

namespace mxc::test {

/// A shader's GLSL with its library key ("vertex", "tables" for mxc's fixed shaders).
struct KeyedShader {
  std::string libraryKey;
  spirv::GlslSource glsl;
};

/// Every corpus document's raster shader at the default tier, every tier and stage of two
/// documents (an OpenPBR material, a procedural Standard Surface one), the vertex stage and the
/// tables' compute shader.
inline std::vector<KeyedShader> corpusShaders(Context& context) {
  std::vector<KeyedShader> out;
  auto add = [&](const std::string& doc, Accuracy accuracy, glsl::ShaderKind kind) {
    CompileRequest request;
    request.document = sharedDir() / doc;
    request.accuracy = accuracy;
    request.stage = kind;
    Compiler compiler(context, std::move(request));
    for (const ir::Material& m : compiler.materials()) {
      glsl::MaterialShader shader = compiler.shader(m);
      out.push_back({std::move(shader.libraryKey), std::move(shader.glsl)});
    }
  };
  for (const std::string& doc : corpusDocuments()) add(doc, Accuracy::Balanced, glsl::ShaderKind::Raster);
  for (const char* doc : {"corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx",
                          "corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx"}) {
    for (Accuracy accuracy : {Accuracy::Fast, Accuracy::Balanced, Accuracy::Reference}) {
      for (glsl::ShaderKind kind : {glsl::ShaderKind::Raster, glsl::ShaderKind::Eval, glsl::ShaderKind::Furnace,
                                    glsl::ShaderKind::Sample}) {
        add(doc, accuracy, kind);
      }
    }
  }
  out.push_back({"vertex", glsl::buildVertexShader()});
  out.push_back({"tables", glsl::buildTablesShader()});
  return out;
}

}  // namespace mxc::test
