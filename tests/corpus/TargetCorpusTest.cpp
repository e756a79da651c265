// Every material of the corpus in every --target language (compiler/target): both stages
// translated, each resource placed, and each text accepted by its language's own checker
// (glslang's GLSL, ESSL and HLSL front ends, naga's WGSL validator; MSL by SPIRV-Cross alone).

#include <gtest/gtest.h>

#include "compiler/glsl/ShaderInterface.h"
#include "compiler/target/Translate.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

class TargetCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(TargetCorpus, EveryMaterialTranslatesToEveryTarget) {
  const std::vector<uint32_t>& vertex = glsl::vertexStageSpirv();
  for (target::Target t : target::allTargets()) {
    if (t == target::Target::Spirv) continue;
    Context context;
    CompileRequest request;
    request.document = sharedDir() / GetParam();
    request.target = t;
    Compiler compiler(context, request);
    ASSERT_FALSE(compiler.materials().empty()) << context.diagnostics.format();
    for (const ir::Material& material : compiler.materials()) {
      const glsl::MaterialShader shader = compiler.shader(material);
      const auto words = compiler.spirv(shader);
      ASSERT_TRUE(words) << target::targetName(t) << " " << material.name << ": " << context.diagnostics.format();
      const auto interface = glsl::shaderInterfaceJson(material, shader, glsl::ShaderKind::Raster, {});
      const auto placements = target::placeResources(target::resourcesOfInterface(interface), t);
      EXPECT_EQ(placements.size(), interface["descriptors"].size());
      EXPECT_TRUE(compiler.translate(*words, spirv::Stage::Fragment, placements, material.name))
          << target::targetName(t) << " " << material.name << ": " << context.diagnostics.format();
      EXPECT_TRUE(compiler.translate(vertex, spirv::Stage::Vertex, placements, "vertex"))
          << target::targetName(t) << ": " << context.diagnostics.format();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, TargetCorpus, ::testing::ValuesIn(corpusDocuments()), corpusTestName);

}  // namespace
}  // namespace mxc::test
