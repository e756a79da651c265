// ModuleCut (compiler/spirv/ModuleCut.h) on small hand-written modules: a member cut from a
// group keeps its own code and nothing of the other members', capabilities follow the code that
// is left, what the cut cannot decide is refused, and the canonical form does not depend on
// what else the module held. Every corpus material is checked by ShaderGroupTest.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "compiler/spirv/ModuleCut.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::test {
namespace {

using Words = std::vector<uint32_t>;

/// A compute shader whose main stores `closure(x)`, with `functions` (the members and the
/// forwarder `closure`) before it.
Words compiled(const std::string& functions) {
  spirv::GlslSource source;
  source.stage = spirv::Stage::Compute;
  source.name = "cut";
  source.text = "#version 450\nlayout(local_size_x = 1) in;\n"
                "layout(set = 0, binding = 0) buffer O { float v[]; } o;\n"
                "layout(set = 0, binding = 1) uniform sampler2D image;\n" +
                functions + "\nvoid main() { o.v[0] = closure(o.v[1]); }\n";
  Diagnostics diagnostics;
  auto words = spirv::compile(source, {}, diagnostics);
  EXPECT_TRUE(words) << diagnostics.format();
  return words.value_or(Words{});
}

Words cut(const Words& module, const std::string& forwarder, const std::string& member) {
  std::string error;
  auto words = spirv::cutModule(module, {forwarder, member}, error);
  EXPECT_TRUE(words) << error;
  return words.value_or(Words{});
}

/// Whether the module holds an instruction of `opcode` whose last word is `last`.
bool has(const Words& words, uint32_t opcode, uint32_t last) {
  for (size_t i = 5; i < words.size() && (words[i] >> 16) != 0; i += words[i] >> 16) {
    if ((words[i] & 0xffffu) == opcode && words[i + (words[i] >> 16) - 1] == last) return true;
  }
  return false;
}

uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

constexpr uint32_t kOpCapability = 17, kOpConstant = 43;
constexpr uint32_t kImageQuery = 50, kFloat64 = 10;

const std::string kMembers =
    "float closure_m0(float x) { return x * 0.25; }\n"
    "float closure_m1(float x) { return x * 0.75 + float(textureSize(image, 0).x); }\n"
    "float closure(float x) { return closure_m0(x) + closure_m1(x); }\n";

TEST(ModuleCut, AMemberKeepsItsCodeAndNotTheOthers) {
  const Words group = compiled(kMembers);
  const Words first = cut(group, "closure", "closure_m0");
  const Words second = cut(group, "closure", "closure_m1");
  EXPECT_EQ(spirv::validate(first), "");
  EXPECT_EQ(spirv::validate(second), "");
  EXPECT_TRUE(has(first, kOpConstant, bits(0.25f)));
  EXPECT_FALSE(has(first, kOpConstant, bits(0.75f)));
  EXPECT_TRUE(has(second, kOpConstant, bits(0.75f)));
  EXPECT_FALSE(has(second, kOpConstant, bits(0.25f)));
  // textureSize needs ImageQuery: the second member's module declares it, the first's not.
  EXPECT_TRUE(has(group, kOpCapability, kImageQuery));
  EXPECT_TRUE(has(second, kOpCapability, kImageQuery));
  EXPECT_FALSE(has(first, kOpCapability, kImageQuery));
  EXPECT_LT(first.size(), group.size());
}

TEST(ModuleCut, AMemberCutFromAGroupIsTheModuleCompiledForItAlone) {
  const Words group = compiled(kMembers);
  // The same member as the only one, under the forwarder's name: the canonical form of that
  // module is the cut's, though glslang numbered and ordered its IDs otherwise.
  const Words alone = compiled("float closure(float x) { return x * 0.75 + float(textureSize(image, 0).x); }\n");
  std::string error;
  const auto canonical = spirv::cutModule(alone, {}, error);
  ASSERT_TRUE(canonical) << error;
  EXPECT_EQ(cut(group, "closure", "closure_m1"), *canonical);
  EXPECT_NE(alone, *canonical) << "glslang's own order is not the canonical one here";
}

TEST(ModuleCut, ACapabilityTheCutCannotDecideIsRefused) {
  // Float64 follows from types, not opcodes: the cut cannot tell whether what is left needs it.
  const Words group = compiled("float closure_m0(float x) { return x; }\n"
                               "float closure_m1(float x) { return float(double(x) * 2.0lf); }\n"
                               "float closure(float x) { return closure_m0(x) + closure_m1(x); }\n");
  ASSERT_TRUE(has(group, kOpCapability, kFloat64));
  std::string error;
  EXPECT_FALSE(spirv::cutModule(group, {"closure", "closure_m0"}, error));
  EXPECT_NE(error.find("capability 10"), std::string::npos) << error;
  // Put in canonical form alone, the module keeps it.
  const auto canonical = spirv::cutModule(group, {}, error);
  ASSERT_TRUE(canonical) << error;
  EXPECT_TRUE(has(*canonical, kOpCapability, kFloat64));
  EXPECT_EQ(spirv::validate(*canonical), "");
}

TEST(ModuleCut, AMissingMemberOrAModuleThatDoesNotParseIsAnError) {
  const Words group = compiled(kMembers);
  std::string error;
  EXPECT_FALSE(spirv::cutModule(group, {"closure", "closure_m7"}, error));
  EXPECT_NE(error.find("closure_m7"), std::string::npos) << error;
  Words broken = group;
  broken.resize(broken.size() / 2);
  EXPECT_FALSE(spirv::cutModule(broken, {}, error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace mxc::test
