// SPIRV-Tools' performance passes through spirv::compile (`mxc compile -O`): small functions are
// inlined into their callers, long ones (counting the callees they would inline) stay
// functions, so a closure that calls its big lobe functions once per lobe does not grow under -O.

#include <gtest/gtest.h>

#include <string>

#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::test {
namespace {

/// How many OpFunction instructions a module has.
size_t functionCount(const std::vector<uint32_t>& words) {
  size_t count = 0;
  for (size_t i = 5; i < words.size();) {
    const uint32_t n = words[i] >> 16;
    if (n == 0) break;
    if ((words[i] & 0xffffu) == 54u) ++count;  // OpFunction
    i += n;
  }
  return count;
}

/// A compute shader whose main calls `body`'s function f twice.
spirv::GlslSource shader(const std::string& body) {
  spirv::GlslSource source;
  source.stage = spirv::Stage::Compute;
  source.name = "opt";
  source.text = "#version 450\nlayout(local_size_x = 1) in;\nlayout(set = 0, binding = 0) buffer O { float v[]; } o;\n" +
                body + "\nvoid main() { o.v[0] = f(o.v[1]) + f(o.v[2]); }\n";
  return source;
}

TEST(SpirvOptimisation, InlinesSmallFunctions) {
  Diagnostics diagnostics;
  auto plain = spirv::compile(shader("float f(float x) { return x * 2.0 + 1.0; }"), {}, diagnostics);
  auto optimized = spirv::compile(shader("float f(float x) { return x * 2.0 + 1.0; }"), {true}, diagnostics);
  ASSERT_TRUE(plain && optimized) << diagnostics.format();
  EXPECT_TRUE(spirv::validate(*optimized).empty());
  EXPECT_EQ(functionCount(*plain), 2u);
  EXPECT_EQ(functionCount(*optimized), 1u) << "f is inlined into main";
  EXPECT_LT(spirv::instructionCount(*optimized), spirv::instructionCount(*plain));
}

TEST(SpirvOptimisation, KeepsLongFunctionsAsCalls) {
  // A loop-free chain of 200 dependent operations: far above the inlining limit.
  std::string body = "float f(float x) {\n  float y = x;\n";
  for (int k = 0; k < 200; ++k) body += "  y = sin(y) * " + std::to_string(k + 2) + ".0 + x;\n";
  body += "  return y;\n}";
  Diagnostics diagnostics;
  auto plain = spirv::compile(shader(body), {}, diagnostics);
  auto optimized = spirv::compile(shader(body), {true}, diagnostics);
  ASSERT_TRUE(plain && optimized) << diagnostics.format();
  EXPECT_TRUE(spirv::validate(*optimized).empty());
  EXPECT_EQ(functionCount(*optimized), 2u) << "f stays a function";
  // Inlined at both calls, the module would hold f's body twice.
  EXPECT_LT(spirv::instructionCount(*optimized), spirv::instructionCount(*plain));
}

// The size that counts is a function's with the small callees it would inline: f is short
// itself but calls h twice; h alone is small (inlined into f), f with it is not.
TEST(SpirvOptimisation, CountsInlinedCalleesInAFunctionsSize) {
  std::string body = "float h(float x) {\n  float y = x;\n";
  for (int k = 0; k < 12; ++k) body += "  y = sin(y) * " + std::to_string(k + 2) + ".0 + x;\n";
  body += "  return y;\n}\nfloat f(float x) { return h(x) + h(x + 1.0); }";
  Diagnostics diagnostics;
  auto plain = spirv::compile(shader(body), {}, diagnostics);
  auto optimized = spirv::compile(shader(body), {true}, diagnostics);
  ASSERT_TRUE(plain && optimized) << diagnostics.format();
  EXPECT_TRUE(spirv::validate(*optimized).empty());
  EXPECT_EQ(functionCount(*plain), 3u);
  EXPECT_EQ(functionCount(*optimized), 2u) << "h is inlined into f, f stays a function";
}

}  // namespace
}  // namespace mxc::test
