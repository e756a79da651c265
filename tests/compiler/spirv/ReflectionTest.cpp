// glslang reflection through spirv::compile: what a harness needs to run GLSL that another
// generator wrote (block bindings and std140 offsets, samplers, stage inputs). Blocks the
// shader never reads are not reported (glslang's reflection lists live blocks), but every
// member of a live block is.

#include <gtest/gtest.h>

#include <algorithm>

#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::test {
namespace {

TEST(SpirvReflection, BlocksMembersAndSamplers) {
  const char* fragment = R"(#version 450
layout (std140, binding=2) uniform Public { float a; vec3 b; mat4 m; int n; };
struct Light { int type; vec3 direction; };
layout (std140, binding=3) uniform Lights { Light u_light[2]; };
layout (binding=5) uniform sampler2D tex;
layout (location = 0) in vec2 uv;
layout (location = 1) in vec3 normal;  // a fragment stage's inputs are not reflected
layout (location = 0) out vec4 color;
void main() { color = vec4(a) + texture(tex, uv) + vec4(normal, float(u_light[0].type)); }
)";
  spirv::Reflection r;
  Diagnostics diagnostics;
  auto words = spirv::compile({fragment, spirv::Stage::Fragment, "test", {}}, {.reflection = &r, .specialization = {}}, diagnostics);
  ASSERT_TRUE(words) << diagnostics.format();

  auto block = [&](const std::string& name) {
    return std::find_if(r.blocks.begin(), r.blocks.end(), [&](const auto& b) { return b.name == name; });
  };
  ASSERT_NE(block("Public"), r.blocks.end());
  EXPECT_EQ(block("Public")->binding, 2);
  ASSERT_NE(block("Lights"), r.blocks.end());
  EXPECT_EQ(block("Lights")->binding, 3);

  auto member = [&](const std::string& name) -> const spirv::Reflection::Member* {
    for (const auto& m : r.members) {
      if (m.name == name) return &m;
    }
    return nullptr;
  };
  // Every member is listed, used or not, at its std140 offset.
  ASSERT_NE(member("a"), nullptr);
  ASSERT_NE(member("b"), nullptr);
  ASSERT_NE(member("m"), nullptr);
  ASSERT_NE(member("n"), nullptr);
  EXPECT_EQ(member("a")->offset, 0);
  EXPECT_EQ(member("b")->offset, 16);
  EXPECT_EQ(member("b")->components, 3);
  EXPECT_EQ(member("m")->offset, 32);
  EXPECT_EQ(member("m")->columns, 4);
  EXPECT_EQ(member("m")->components, 16);
  EXPECT_EQ(member("n")->offset, 96);
  EXPECT_EQ(member("n")->scalar, spirv::Reflection::Scalar::Int);
  const spirv::Reflection::Member* direction = member("u_light[1].direction");
  ASSERT_NE(direction, nullptr);
  EXPECT_EQ(direction->offset, 32 + 16);  // array stride of the struct: 32 bytes

  ASSERT_EQ(r.samplers.size(), 1u);
  EXPECT_EQ(r.samplers[0].name, "tex");
  EXPECT_EQ(r.samplers[0].binding, 5);
}

TEST(SpirvReflection, VertexStageInputs) {
  const char* vertex = R"(#version 450
layout (location = 0) in vec3 i_position;
layout (location = 1) in vec2 i_texcoord_0;
void main() { gl_Position = vec4(i_position + vec3(i_texcoord_0, 0.0), 1.0); }
)";
  spirv::Reflection r;
  Diagnostics diagnostics;
  ASSERT_TRUE(spirv::compile({vertex, spirv::Stage::Vertex, "test", {}}, {.reflection = &r, .specialization = {}}, diagnostics))
      << diagnostics.format();
  ASSERT_EQ(r.inputs.size(), 2u);
  for (const auto& in : r.inputs) {
    if (in.name == "i_position") {
      EXPECT_EQ(in.location, 0);
      EXPECT_EQ(in.components, 3);
    } else {
      EXPECT_EQ(in.name, "i_texcoord_0");
      EXPECT_EQ(in.location, 1);
      EXPECT_EQ(in.components, 2);
    }
  }
}

}  // namespace
}  // namespace mxc::test
