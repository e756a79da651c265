// Every corpus document compiles, for every material and every shader kind (raster fragment,
// eval compute, furnace compute), to a SPIR-V module that SPIRV-Tools validates.

#include <gtest/gtest.h>
#include <unistd.h>

#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

class SpirvCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(SpirvCorpus, EveryShaderKindValidates) {
  Context context;
  std::vector<ir::Material> materials = lowerFile(context, sharedDir() / GetParam());
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  ASSERT_FALSE(materials.empty());
  for (const ir::Material& m : materials) {
    for (glsl::ShaderKind kind : {glsl::ShaderKind::Raster, glsl::ShaderKind::Eval, glsl::ShaderKind::Furnace}) {
      glsl::MaterialShader shader = buildShader(m, kind);
      Diagnostics diagnostics;
      std::optional<std::vector<uint32_t>> words = compileShader(shader, {}, diagnostics);
      ASSERT_TRUE(words.has_value()) << m.name << " (" << glsl::shaderKindName(kind) << "): " << diagnostics.format();
      EXPECT_EQ(spirv::validate(*words), "") << m.name << " (" << glsl::shaderKindName(kind) << ")";
      EXPECT_EQ(shader.glsl.origins.size(),
                static_cast<size_t>(std::count(shader.glsl.text.begin(), shader.glsl.text.end(), '\n')));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, SpirvCorpus, ::testing::ValuesIn(corpusDocuments()),
                         corpusTestName);

}  // namespace
}  // namespace mxc::test
