// Materials of one library compiled as one shader (glsl/ShaderGroup.h) and each material's
// module cut from it (spirv/ModuleCut.h): for every material of the corpus, the cut module is
// valid and is, byte for byte, the canonical form of the module compiled for it alone, also
// when the group declares more textures than the material reads.

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "compiler/driver/Compiler.h"
#include "compiler/glsl/ShaderGroup.h"
#include "compiler/spirv/ModuleCut.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

using Words = std::vector<uint32_t>;

Words compiled(const spirv::GlslSource& source, Diagnostics& diagnostics) {
  auto words = spirv::compile(source, {}, diagnostics);
  EXPECT_TRUE(words) << source.name << ": " << diagnostics.format();
  return words.value_or(Words{});
}

Words cut(const Words& module, const spirv::CutRequest& request) {
  std::string error;
  auto words = spirv::cutModule(module, request, error);
  EXPECT_TRUE(words) << error;
  return words.value_or(Words{});
}

TEST(ShaderGroup, EveryCorpusMaterialCutFromItsGroupIsItsOwnModule) {
  Context context;
  std::vector<glsl::MaterialShader> shaders;
  for (const std::string& doc : corpusDocuments()) {
    CompileRequest request;
    request.document = sharedDir() / doc;
    Compiler compiler(context, std::move(request));
    for (const ir::Material& m : compiler.materials()) shaders.push_back(compiler.shader(m));
  }
  ASSERT_GE(shaders.size(), 70u) << context.diagnostics.format();
  std::map<std::string, std::vector<const glsl::MaterialShader*>> groups;
  for (const glsl::MaterialShader& s : shaders) groups[s.libraryKey].push_back(&s);
  EXPECT_LE(groups.size(), shaders.size() / 3) << "the corpus's materials share a handful of libraries";
  size_t checked = 0, ofSeveralTextureCounts = 0;
  for (const auto& [key, members] : groups) {
    if (members.size() < 2) continue;
    std::set<size_t> textureCounts;
    for (const glsl::MaterialShader* m : members) textureCounts.insert(m->texturesEnd - m->texturesFirst);
    if (textureCounts.size() > 1) ++ofSeveralTextureCounts;
    const Words group = compiled(glsl::groupSource(members), context.diagnostics);
    for (size_t k = 0; k < members.size(); ++k) {
      const Words mine = cut(group, {glsl::kClosureFunction, glsl::groupMemberFunction(k)});
      const Words alone = cut(compiled(members[k]->glsl, context.diagnostics), {});
      EXPECT_EQ(spirv::validate(mine), "") << members[k]->glsl.name;
      EXPECT_EQ(mine, alone) << members[k]->glsl.name << " cut from " << members.size()
                             << " materials differs from its own module";
      ++checked;
    }
  }
  EXPECT_GE(checked, 50u);
  // Materials that read different numbers of textures (the brick and the calibration sphere
  // of the Standard Surface examples) share a library.
  EXPECT_GE(ofSeveralTextureCounts, 1u);
}

}  // namespace
}  // namespace mxc::test
