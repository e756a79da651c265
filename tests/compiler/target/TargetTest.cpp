// The --target languages (compiler/target): where each binds the shader interface's descriptors,
// and that a material's stages translated to each bind them there, in both stages alike, pass
// their language's own checks, and need no subgroup operations.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <regex>

#include "compiler/glsl/Bindings.h"
#include "compiler/glsl/ShaderInterface.h"
#include "compiler/target/NagaTranslator.h"
#include "compiler/target/Translate.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

using target::Placement;
using target::Resource;
using target::Target;

/// The descriptors of a raster shader with one texture, and a written storage buffer.
std::vector<Resource> someResources() {
  using K = Resource::Kind;
  return {{0, 0, K::Texture, false, "mxc_tables"},          {0, 1, K::UniformBuffer, false, "MxcView"},
          {0, 2, K::StorageBuffer, false, "MxcParameters"}, {0, 4, K::StorageBuffer, true, "MxcOutput"},
          {0, 5, K::Texture, false, "mxc_texture_0"},       {1, 0, K::Texture, false, "mxc_env_radiance"},
          {1, 1, K::StorageBuffer, false, "MxcEnvDistribution"}};
}

const Placement& placed(const std::vector<Placement>& placements, const std::string& name) {
  for (const Placement& p : placements) {
    if (p.resource.name == name) return p;
  }
  throw std::runtime_error("no placement of " + name);
}

TEST(TargetNames, RoundTripThroughNamesAndExtensions) {
  for (Target t : target::allTargets()) {
    EXPECT_EQ(target::parseTarget(target::targetName(t)), t);
    EXPECT_EQ(target::targetOfExtension(target::fileExtension(t)), t);
  }
  EXPECT_EQ(target::targetOfExtension(".msl"), Target::Msl);
  EXPECT_FALSE(target::targetOfExtension(".frag").has_value());
  EXPECT_FALSE(target::parseTarget("spir-v").has_value());
  EXPECT_EQ(target::targetNames(), "spirv|glsl|essl|msl|hlsl|wgsl");
}

TEST(TargetPlacement, OpenGlNumbersEachClassApartInSetAndBindingOrder) {
  const auto p = target::placeResources(someResources(), Target::Glsl);
  EXPECT_EQ(placed(p, "mxc_tables").binding, 0);
  EXPECT_EQ(placed(p, "mxc_texture_0").binding, 1);
  EXPECT_EQ(placed(p, "mxc_env_radiance").binding, 2);
  EXPECT_EQ(placed(p, "MxcView").binding, 0);
  EXPECT_EQ(placed(p, "MxcParameters").binding, 0);
  EXPECT_EQ(placed(p, "MxcOutput").binding, 1);
  EXPECT_EQ(placed(p, "MxcEnvDistribution").binding, 2);
}

TEST(TargetPlacement, MetalSharesOneBufferTableAndPairsSamplersWithTextures) {
  const auto p = target::placeResources(someResources(), Target::Msl);
  EXPECT_EQ(placed(p, "MxcView").buffer, 0);
  EXPECT_EQ(placed(p, "MxcParameters").buffer, 1);
  EXPECT_EQ(placed(p, "MxcOutput").buffer, 2);
  EXPECT_EQ(placed(p, "MxcEnvDistribution").buffer, 3);
  EXPECT_EQ(placed(p, "mxc_texture_0").texture, 1);
  EXPECT_EQ(placed(p, "mxc_texture_0").sampler, 1);
  EXPECT_EQ(placed(p, "mxc_env_radiance").texture, 2);
}

TEST(TargetPlacement, HlslRegistersFollowBindingAndSpaceFollowsSet) {
  const auto p = target::placeResources(someResources(), Target::Hlsl);
  EXPECT_EQ(target::placementJson(placed(p, "MxcView"), Target::Hlsl),
            nlohmann::json({{"register", "b1"}, {"space", 0}}));
  EXPECT_EQ(target::placementJson(placed(p, "MxcParameters"), Target::Hlsl),
            nlohmann::json({{"register", "t2"}, {"space", 0}}));
  EXPECT_EQ(target::placementJson(placed(p, "MxcOutput"), Target::Hlsl),
            nlohmann::json({{"register", "u4"}, {"space", 0}}));
  EXPECT_EQ(target::placementJson(placed(p, "mxc_env_radiance"), Target::Hlsl),
            nlohmann::json({{"register", "t0"}, {"sampler", "s0"}, {"space", 1}}));
}

TEST(TargetPlacement, WgslGivesEachTextureASamplerBindingAboveIt) {
  const auto p = target::placeResources(someResources(), Target::Wgsl);
  EXPECT_EQ(placed(p, "mxc_texture_0").binding, 5);
  EXPECT_EQ(placed(p, "mxc_texture_0").samplerBinding, 5 + int(glsl::kSeparateSamplerOffset));
  EXPECT_EQ(placed(p, "MxcEnvDistribution").binding, 1);
  EXPECT_EQ(placed(p, "MxcView").samplerBinding, -1);
}

TEST(TargetPlacement, DoesNotDependOnTheOrderTheDescriptorsAreListedIn) {
  std::vector<Resource> shuffled = someResources();
  std::mt19937 random(7);
  for (Target t : target::allTargets()) {
    const auto reference = target::placeResources(someResources(), t);
    for (int round = 0; round < 5; ++round) {
      std::shuffle(shuffled.begin(), shuffled.end(), random);
      const auto p = target::placeResources(shuffled, t);
      for (const Placement& want : reference) {
        EXPECT_EQ(target::placementJson(placed(p, want.resource.name), t), target::placementJson(want, t))
            << target::targetName(t) << " " << want.resource.name;
      }
    }
  }
}

/// A document's first material in `target`: both stages and the placements they were given.
struct Translated {
  std::string fragment, vertex;
  std::vector<Placement> placements;
  nlohmann::json interface;
};

Translated translateDocument(const std::filesystem::path& document, Target target) {
  Context context;
  CompileRequest request;
  request.document = document;
  request.target = target;
  Compiler compiler(context, request);
  Translated out;
  if (compiler.materials().empty()) {
    ADD_FAILURE() << context.diagnostics.format();
    return out;
  }
  const ir::Material& material = compiler.materials().front();
  const glsl::MaterialShader shader = compiler.shader(material);
  const auto words = compiler.spirv(shader);
  if (!words) {
    ADD_FAILURE() << context.diagnostics.format();
    return out;
  }
  out.interface = glsl::shaderInterfaceJson(material, shader, glsl::ShaderKind::Raster, {});
  out.placements = target::placeResources(target::resourcesOfInterface(out.interface), target);
  auto fragment = compiler.translate(*words, spirv::Stage::Fragment, out.placements, "fragment");
  auto vertex = compiler.translate(glsl::vertexStageSpirv(), spirv::Stage::Vertex, out.placements, "vertex");
  EXPECT_TRUE(fragment && vertex) << context.diagnostics.format();
  if (fragment) out.fragment = fragment->text;
  if (vertex) out.vertex = vertex->text;
  return out;
}

/// A brick material with six textures: every kind of descriptor a raster shader has.
std::filesystem::path brick() {
  return sharedDir() / "corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx";
}

int firstNumber(const std::string& text, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern))) return -1;
  return std::stoi(m[1].str());
}

TEST(TargetTranslation, GlslBindsEachBlockAndTextureWhereThePlacementSays) {
  for (Target t : {Target::Glsl, Target::Essl}) {
    const Translated out = translateDocument(brick(), t);
    const int view = placed(out.placements, "MxcView").binding;
    EXPECT_EQ(firstNumber(out.fragment, R"(layout\(binding = (\d+), std140\) uniform MxcView)"), view);
    EXPECT_EQ(firstNumber(out.vertex, R"(layout\(binding = (\d+), std140\) uniform MxcView)"), view);
    EXPECT_EQ(firstNumber(out.fragment, R"(layout\(binding = (\d+)\) uniform (?:highp )?sampler2D mxc_texture_0;)"),
              placed(out.placements, "mxc_texture_0").binding);
    EXPECT_EQ(firstNumber(out.fragment, R"(layout\(binding = (\d+), std\d+\) readonly buffer MxcParameters)"),
              placed(out.placements, "MxcParameters").binding);
    EXPECT_EQ(out.fragment.find("subgroup"), std::string::npos) << "hosts of " << target::targetName(t) << " need no subgroups";
  }
}

TEST(TargetTranslation, MetalStagesAgreeOnTheViewBuffer) {
  const Translated out = translateDocument(brick(), Target::Msl);
  const int view = placed(out.placements, "MxcView").buffer;
  EXPECT_EQ(firstNumber(out.fragment, R"(MxcView& mxc_view \[\[buffer\((\d+)\)\]\])"), view);
  EXPECT_EQ(firstNumber(out.vertex, R"(MxcView& mxc_view \[\[buffer\((\d+)\)\]\])"), view);
  EXPECT_EQ(firstNumber(out.fragment, R"(mxc_texture_0 \[\[texture\((\d+)\)\]\])"),
            placed(out.placements, "mxc_texture_0").texture);
  EXPECT_EQ(out.fragment.find("simd_"), std::string::npos);
}

TEST(TargetTranslation, HlslRegistersAreThePlacements) {
  const Translated out = translateDocument(brick(), Target::Hlsl);
  EXPECT_NE(out.fragment.find("cbuffer MxcView : register(b1, space0)"), std::string::npos);
  EXPECT_NE(out.vertex.find("cbuffer MxcView : register(b1, space0)"), std::string::npos);
  EXPECT_NE(out.fragment.find("mxc_texture_0 : register(t5, space0)"), std::string::npos);
  EXPECT_NE(out.fragment.find("mxc_env_radiance : register(t0, space1)"), std::string::npos);
  EXPECT_EQ(out.fragment.find("Wave"), std::string::npos);
}

TEST(TargetTranslation, WgslHasSeparateSamplersAndNoSpecialization) {
  ASSERT_FALSE(target::nagaProgram().empty()) << "naga is not installed: scripts/setup installs it";
  const Translated out = translateDocument(brick(), Target::Wgsl);
  const int texture = placed(out.placements, "mxc_texture_0").binding;
  const int sampler = placed(out.placements, "mxc_texture_0").samplerBinding;
  EXPECT_NE(out.fragment.find(fmt::format("@group(0) @binding({}) \nvar mxc_texture_0_texture: texture_2d<f32>;", texture)),
            std::string::npos);
  EXPECT_NE(out.fragment.find(fmt::format("@group(0) @binding({}) \nvar mxc_texture_0_sampler: sampler;", sampler)),
            std::string::npos);
  EXPECT_EQ(out.fragment.find("override "), std::string::npos) << "specialization constants are fixed at their defaults";
  EXPECT_EQ(out.fragment.find("subgroup"), std::string::npos);
  EXPECT_NE(out.fragment.find("@fragment"), std::string::npos);
  EXPECT_NE(out.vertex.find("@vertex"), std::string::npos);
}

TEST(TargetTranslation, TheSpirvTargetKeepsSubgroupsAndCombinedSamplers) {
  Context context;
  CompileRequest request;
  request.document = brick();
  Compiler compiler(context, request);
  ASSERT_FALSE(compiler.materials().empty());
  const glsl::MaterialShader shader = compiler.shader(compiler.materials().front());
  EXPECT_NE(shader.glsl.text.find("#define MXC_SUBGROUPS"), std::string::npos);
  EXPECT_EQ(shader.glsl.text.find("#define MXC_SEPARATE_SAMPLERS"), std::string::npos);
  const auto json = glsl::shaderInterfaceJson(compiler.materials().front(), shader, glsl::ShaderKind::Raster, {});
  EXPECT_EQ(json["requires"].size(), 1u);
}

TEST(TargetChecks, RejectInvalidTextInEachLanguage) {
  const std::string glsl = "#version 450\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec3(1.0); }\n";
  EXPECT_NE(spirv::checkSource(glsl, spirv::Language::OpenGl, spirv::Stage::Fragment, "main"), "");
  const std::string essl = "#version 320 es\nprecision highp float;\nlayout(location = 0) out vec4 o;\n"
                           "void main() { o = texture2D(x, vec2(0.0)); }\n";
  EXPECT_NE(spirv::checkSource(essl, spirv::Language::OpenGlEs, spirv::Stage::Fragment, "main"), "");
  const std::string hlsl = "float4 main() : SV_Target0 { return undefinedName; }\n";
  EXPECT_NE(spirv::checkSource(hlsl, spirv::Language::Hlsl, spirv::Stage::Fragment, "main"), "");
  // And accept valid text, so that the rejections above are the checks' doing.
  EXPECT_EQ(spirv::checkSource("#version 450\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(1.0); }\n",
                               spirv::Language::OpenGl, spirv::Stage::Fragment, "main"),
            "");
  EXPECT_EQ(spirv::checkSource("float4 main() : SV_Target0 { return float4(1, 0, 0, 1); }\n", spirv::Language::Hlsl,
                               spirv::Stage::Fragment, "main"),
            "");
}

TEST(TargetChecks, AMissingNagaIsNamedWithTheWayToInstallIt) {
  const char* saved = std::getenv("MXC_NAGA");
  const std::string previous = saved ? saved : "";
  ::setenv("MXC_NAGA", "/nonexistent/naga", 1);
  target::Translation out;
  std::string error;
  EXPECT_FALSE(target::nagaTranslate({0x07230203u, 0x00010300u, 0u, 1u, 0u}, out, error));
  EXPECT_NE(error.find("cargo install naga-cli"), std::string::npos) << error;
  if (saved) {
    ::setenv("MXC_NAGA", previous.c_str(), 1);
  } else {
    ::unsetenv("MXC_NAGA");
  }
}

TEST(TargetChecks, NagaRejectingAModuleIsReportedWithItsMessage) {
  ASSERT_FALSE(target::nagaProgram().empty());
  target::Translation out;
  std::string error;
  // A header and nothing else: no entry point, no memory model.
  EXPECT_FALSE(target::nagaTranslate({0x07230203u, 0x00010300u, 0u, 1u, 0u}, out, error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace mxc::test
