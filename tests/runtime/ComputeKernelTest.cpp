// The Vulkan harness on the default device (lavapipe in CI): a compute kernel compiled with
// glslang runs and writes what it should, with the validation layer on and silent.

#include "runtime/ComputeKernel.h"

#include <gtest/gtest.h>

#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::rt {
namespace {

TEST(ComputeKernel, RunsAGlslKernelWithValidationOn) {
  VulkanContext context({"", true});
  spirv::GlslSource source;
  source.stage = spirv::Stage::Compute;
  source.name = "test kernel";
  source.text =
      "#version 450\nlayout(local_size_x = 64) in;\n"
      "layout(set = 0, binding = 0) buffer Out { float v[]; } outBuffer;\n"
      "layout(push_constant) uniform Push { float scale; } push;\n"
      "void main() { uint i = gl_GlobalInvocationID.x; outBuffer.v[i] = float(i) * push.scale; }\n";
  Diagnostics diagnostics;
  auto words = spirv::compile(source, {}, diagnostics);
  ASSERT_TRUE(words.has_value()) << diagnostics.format();
  EXPECT_GT(spirv::instructionCount(*words), 10u);
  Buffer buffer = context.createBuffer(256 * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  {
    ComputeKernel kernel(context, *words, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, sizeof(float));
    kernel.descriptors().bind(0, buffer);
    const float scale = 2.5f;
    kernel.dispatch(4, 1, &scale);
  }
  const auto* values = static_cast<const float*>(buffer.mapped);
  EXPECT_FLOAT_EQ(values[0], 0.0f);
  EXPECT_FLOAT_EQ(values[255], 637.5f);
  context.destroy(buffer);
  EXPECT_TRUE(context.validationMessages().empty()) << context.validationMessages().front();
}

TEST(SpirvCompiler, ErrorsMapToTheGeneratingElement) {
  SourceFile doc("material.mtlx", "<materialx>\n  <node/>\n</materialx>\n");
  spirv::GlslSource source;
  source.stage = spirv::Stage::Compute;
  source.name = "material M (compute)";
  source.text = "#version 450\nlayout(local_size_x = 1) in;\nvoid main() { float x = undefined_thing; }\n";
  source.origins = {{}, {}, {&doc, 14}};  // line 3 came from the <node> element
  Diagnostics diagnostics;
  EXPECT_FALSE(spirv::compile(source, {}, diagnostics).has_value());
  ASSERT_TRUE(diagnostics.hasErrors());
  const Diagnostic& e = diagnostics.all().front();
  EXPECT_EQ(e.location.str(), "material.mtlx:2:3");
  EXPECT_NE(e.message.find("GLSL for material M (compute) does not compile (generated line 3)"), std::string::npos)
      << e.message;
  EXPECT_NE(e.message.find("undefined_thing"), std::string::npos);
}

}  // namespace
}  // namespace mxc::rt
