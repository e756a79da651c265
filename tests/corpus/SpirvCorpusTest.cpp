// Every corpus document compiles, for every material and every shader kind (raster fragment,
// eval compute, furnace compute) and every accuracy tier, to a SPIR-V module that SPIRV-Tools
// validates.

#include <gtest/gtest.h>
#include <unistd.h>

#include <fmt/format.h>

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
    for (Accuracy accuracy : kAccuracies) {
      CompileRequest request;
      request.accuracy = accuracy;
      for (glsl::ShaderKind kind : {glsl::ShaderKind::Raster, glsl::ShaderKind::Eval, glsl::ShaderKind::Furnace}) {
        const std::string what = fmt::format("{} ({}, {})", m.name, glsl::shaderKindName(kind), accuracyName(accuracy));
        glsl::MaterialShader shader = buildShader(m, kind, request);
        Diagnostics diagnostics;
        std::optional<std::vector<uint32_t>> words = compileShader(shader, {}, diagnostics);
        ASSERT_TRUE(words.has_value()) << what << ": " << diagnostics.format();
        EXPECT_EQ(spirv::validate(*words), "") << what;
        EXPECT_EQ(shader.glsl.origins.size(),
                  static_cast<size_t>(std::count(shader.glsl.text.begin(), shader.glsl.text.end(), '\n')));
        // The fast tier declares no table (its albedos are analytic fits); the balanced tier's
        // module names the tables' sampler (the OpName string, NUL-terminated).
        const std::string_view bytes(reinterpret_cast<const char*>(words->data()), words->size() * 4);
        EXPECT_EQ(bytes.find(std::string_view("mxc_tables\0", 11)) == std::string_view::npos, accuracy == Accuracy::Fast)
            << what;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, SpirvCorpus, ::testing::ValuesIn(corpusDocuments()),
                         corpusTestName);

}  // namespace
}  // namespace mxc::test
