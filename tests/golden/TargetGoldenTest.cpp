// Golden shaders of the --target languages: two corpus documents (an OpenPBR material without
// textures, a Standard Surface one with six) in GLSL, ESSL, MSL, HLSL and WGSL, both stages,
// committed under generated/targets/ and compared here, so that a change of what SPIRV-Cross or
// naga writes (or of the placements) shows in review. Every corpus material is translated and
// checked by tests/corpus/TargetCorpusTest.cpp; scripts/update-goldens rewrites these.

#include <gtest/gtest.h>

#include "compiler/glsl/ShaderInterface.h"
#include "compiler/target/Translate.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDocuments[] = {"corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx",
                                      "corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx"};

/// Both stages of every material of `relative` in `t`, one after the other, and the placements.
std::string translated(const std::string& relative, target::Target t) {
  Context context;
  CompileRequest request;
  request.document = sharedDir() / relative;
  request.target = t;
  Compiler compiler(context, request);
  std::string out;
  for (const ir::Material& material : compiler.materials()) {
    const glsl::MaterialShader shader = compiler.shader(material);
    const auto words = compiler.spirv(shader);
    if (!words) break;
    const auto interface = glsl::shaderInterfaceJson(material, shader, glsl::ShaderKind::Raster, {});
    const auto placements = target::placeResources(target::resourcesOfInterface(interface), t);
    out += "// ==== " + relative + ": material " + material.name + ", placements ====\n";
    for (const target::Placement& p : placements) {
      out += "// " + p.resource.name + " " + target::placementJson(p, t).dump() + "\n";
    }
    const auto fragment = compiler.translate(*words, spirv::Stage::Fragment, placements, material.name);
    const auto vertexText = compiler.translate(glsl::vertexStageSpirv(), spirv::Stage::Vertex, placements, "vertex");
    if (!fragment || !vertexText) break;
    out += "// ==== fragment (" + fragment->entryPoint + ") ====\n" + fragment->text;
    out += "// ==== vertex (" + vertexText->entryPoint + ") ====\n" + vertexText->text;
  }
  if (context.diagnostics.hasErrors()) out += "\n" + context.diagnostics.format();
  return out;
}

class TargetGolden : public ::testing::TestWithParam<target::Target> {};

TEST_P(TargetGolden, MatchesCommittedShaders) {
  const target::Target t = GetParam();
  for (const char* relative : kDocuments) {
    const fs::path golden = sourceDir() / "generated/targets" /
                            (fs::path(relative).stem().string() + std::string(target::fileExtension(t)));
    matchGolden(golden, translated(relative, t), "generated/targets/");
  }
}

INSTANTIATE_TEST_SUITE_P(Targets, TargetGolden,
                         ::testing::Values(target::Target::Glsl, target::Target::Essl, target::Target::Msl,
                                           target::Target::Hlsl, target::Target::Wgsl),
                         [](const ::testing::TestParamInfo<target::Target>& param) {
                           return std::string(target::targetName(param.param));
                         });

}  // namespace
}  // namespace mxc::test
