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

/// A function `name` of `operations` dependent sin-multiply-adds (about 6.5 instructions each).
std::string chain(const std::string& name, int operations) {
  std::string body = "float " + name + "(float x) {\n  float y = x;\n";
  for (int k = 0; k < operations; ++k) body += "  y = sin(y) * " + std::to_string(k + 2) + ".0 + x;\n";
  return body + "  return y;\n}\n";
}

/// The shader's module without and with -O, and the function count and size of each.
struct Modules {
  size_t plainFunctions = 0, optimizedFunctions = 0;
  size_t plainSize = 0, optimizedSize = 0;
};

Modules compileBoth(const std::string& body) {
  Diagnostics diagnostics;
  auto plain = spirv::compile(shader(body), {}, diagnostics);
  auto optimized = spirv::compile(shader(body), {.optimize = true, .reflection = nullptr, .specialization = {}}, diagnostics);
  Modules m;
  EXPECT_TRUE(plain && optimized) << diagnostics.format();
  if (!plain || !optimized) return m;
  EXPECT_TRUE(spirv::validate(*optimized).empty());
  return {functionCount(*plain), functionCount(*optimized), spirv::instructionCount(*plain),
          spirv::instructionCount(*optimized)};
}

TEST(SpirvOptimisation, InlinesSmallFunctions) {
  Modules m = compileBoth("float f(float x) { return x * 2.0 + 1.0; }");
  EXPECT_EQ(m.plainFunctions, 2u);
  EXPECT_EQ(m.optimizedFunctions, 1u) << "f is inlined into main";
  EXPECT_LT(m.optimizedSize, m.plainSize);
}

TEST(SpirvOptimisation, KeepsLongFunctionsAsCalls) {
  // 200 operations: far above the inlining limit.
  Modules m = compileBoth(chain("f", 200));
  EXPECT_EQ(m.optimizedFunctions, 2u) << "f stays a function";
  // Inlined at both calls, the module would hold f's body twice.
  EXPECT_LT(m.optimizedSize, m.plainSize);
}

// The size that counts is a function's with the small callees it would inline: f is short
// itself but calls h (12 operations, 79 instructions) twice; h alone is inlined into f, f with
// it is over the limit.
TEST(SpirvOptimisation, CountsInlinedCalleesInAFunctionsSize) {
  Modules m = compileBoth(chain("h", 12) + "float f(float x) { return h(x) + h(x + 1.0); }");
  EXPECT_EQ(m.plainFunctions, 3u);
  EXPECT_EQ(m.optimizedFunctions, 2u) << "h is inlined into f, f stays a function";
}

// Specialization constants fixed before the passes fold what they decide: the branch a value
// does not take is gone from the module, as from a pipeline created with that value.
TEST(SpirvOptimisation, FixedSpecializationConstantsFoldTheirBranches) {
  const std::string body = "layout(constant_id = 1) const int kMode = -1;\n" + chain("heavy", 40) +
                           "float f(float x) { return kMode == 2 ? heavy(x) : x + 1.0; }";
  Diagnostics diagnostics;
  spirv::CompileOptions open{.optimize = true, .reflection = nullptr, .specialization = {}};
  spirv::CompileOptions light{.optimize = true, .reflection = nullptr, .specialization = {{1u, 0}}};
  spirv::CompileOptions heavy{.optimize = true, .reflection = nullptr, .specialization = {{1u, 2}}};
  auto a = spirv::compile(shader(body), open, diagnostics);
  auto b = spirv::compile(shader(body), light, diagnostics);
  auto c = spirv::compile(shader(body), heavy, diagnostics);
  ASSERT_TRUE(a && b && c) << diagnostics.format();
  EXPECT_TRUE(spirv::validate(*b).empty());
  EXPECT_LT(spirv::instructionCount(*b) + 100, spirv::instructionCount(*a)) << "the heavy branch is folded away";
  EXPECT_GT(spirv::instructionCount(*c), spirv::instructionCount(*b) + 100) << "the heavy branch is kept";
}

}  // namespace
}  // namespace mxc::test

namespace mxc::test {
namespace {

// Validation skips SPIRV-Tools' friendly names for speed (they were a quarter of a material's
// compile time); a module that fails is validated again with them, so the message still names
// the ids it is about: here an entry point that is the buffer variable `o`, not a function.
TEST(SpirvValidation, AnInvalidModulesMessageNamesItsIds) {
  Diagnostics diagnostics;
  auto words = spirv::compile(shader(chain("f", 1)), {}, diagnostics);
  ASSERT_TRUE(words) << diagnostics.format();
  uint32_t buffer = 0;  // the result id of the OpVariable (opcode 59) of the buffer o
  size_t entryPoint = 0;  // where OpEntryPoint (opcode 15) is: model, function id, name, ...
  for (size_t i = 5; i < words->size();) {
    const uint32_t n = (*words)[i] >> 16;
    const uint32_t opcode = (*words)[i] & 0xffffu;
    if (opcode == 59u && (*words)[i + 3] != 7u) buffer = (*words)[i + 2];  // not a Function-storage local
    if (opcode == 15u) entryPoint = i;
    i += n;
  }
  ASSERT_NE(buffer, 0u);
  ASSERT_NE(entryPoint, 0u);
  (*words)[entryPoint + 2] = buffer;
  const std::string message = spirv::validate(*words);
  EXPECT_NE(message.find("[%o]"), std::string::npos) << message;  // with the names off: "[%20]"
}

}  // namespace
}  // namespace mxc::test
