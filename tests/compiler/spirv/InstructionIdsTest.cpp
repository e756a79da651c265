// InstructionIds (compiler/spirv/InstructionIds.h) against SPIRV-Tools' binary parser: for every
// instruction of every corpus module (and every tier and stage of two documents), the same
// result word and the same used-ID words; and the modules the walk refuses.

#include <gtest/gtest.h>

#include <map>

#include <fmt/format.h>
#include <spirv-tools/libspirv.h>

#include "compiler/spirv/InstructionIds.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "support/ShaderSupport.h"

namespace mxc::test {
namespace {

using Words = std::vector<uint32_t>;

/// Per instruction: "opcode r<offset> u<offset>..." as SPIRV-Tools' parser classifies it.
std::vector<std::string> bySpirvTools(const Words& module) {
  std::vector<std::string> out;
  auto onInstruction = [](void* user, const spv_parsed_instruction_t* parsed) -> spv_result_t {
    std::string s = fmt::format("{}", parsed->opcode);
    for (uint16_t i = 0; i < parsed->num_operands; ++i) {
      const spv_parsed_operand_t& o = parsed->operands[i];
      if (o.type == SPV_OPERAND_TYPE_RESULT_ID) s += fmt::format(" r{}", o.offset);
    }
    for (uint16_t i = 0; i < parsed->num_operands; ++i) {
      const spv_parsed_operand_t& o = parsed->operands[i];
      if (o.type == SPV_OPERAND_TYPE_ID || o.type == SPV_OPERAND_TYPE_TYPE_ID ||
          o.type == SPV_OPERAND_TYPE_MEMORY_SEMANTICS_ID || o.type == SPV_OPERAND_TYPE_SCOPE_ID) {
        s += fmt::format(" u{}", o.offset);
      }
    }
    static_cast<std::vector<std::string>*>(user)->push_back(s);
    return SPV_SUCCESS;
  };
  spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_1);
  EXPECT_EQ(spvBinaryParse(context, &out, module.data(), module.size(), nullptr, onInstruction, nullptr),
            SPV_SUCCESS);
  spvContextDestroy(context);
  return out;
}

std::vector<std::string> byWalk(const Words& module) {
  std::string error;
  const std::optional<spirv::ModuleIds> ids = spirv::instructionIds(module, error);
  EXPECT_TRUE(ids) << error;
  std::vector<std::string> out;
  if (!ids) return out;
  for (const spirv::InstructionIds& inst : ids->instructions) {
    std::string s = fmt::format("{}", inst.opcode);
    if (inst.resultAt) s += fmt::format(" r{}", inst.resultAt);
    for (uint16_t k = 0; k < inst.useCount; ++k) s += fmt::format(" u{}", ids->uses[inst.firstUse + k]);
    out.push_back(s);
  }
  return out;
}

void expectSameIds(const Words& module, const std::string& name) {
  const std::vector<std::string> expected = bySpirvTools(module);
  const std::vector<std::string> walked = byWalk(module);
  ASSERT_EQ(walked.size(), expected.size()) << name;
  size_t differences = 0;
  for (size_t i = 0; i < expected.size() && differences < 5; ++i) {
    if (walked[i] != expected[i]) {
      ADD_FAILURE() << name << ": instruction " << i << ": walk '" << walked[i] << "', SPIRV-Tools '" << expected[i]
                    << "'";
      ++differences;
    }
  }
}

TEST(InstructionIds, EveryCorpusModuleHasTheIdsSpirvToolsFinds) {
  Context context;
  std::map<std::string, spirv::GlslSource> sources;  // one shader per distinct text
  for (KeyedShader& s : corpusShaders(context)) sources.emplace(s.glsl.text, std::move(s.glsl));
  ASSERT_GE(sources.size(), 70u) << context.diagnostics.format();
  for (const auto& [text, source] : sources) {
    Diagnostics diagnostics;
    const auto words = spirv::compile(source, {}, diagnostics);
    ASSERT_TRUE(words) << source.name << ": " << diagnostics.format();
    expectSameIds(*words, source.name);
    // The optimiser writes other instructions (OpPhi, OpSelect, OpCompositeInsert ...).
    spirv::CompileOptions optimized;
    optimized.optimize = true;
    if (source.name.find("Default") != std::string::npos) {
      const auto o = spirv::compile(source, optimized, diagnostics);
      ASSERT_TRUE(o) << diagnostics.format();
      expectSameIds(*o, source.name + " (optimised)");
    }
  }
}

TEST(InstructionIds, ModulesItCannotReadAreRefused) {
  std::string error;
  EXPECT_FALSE(spirv::instructionIds(Words{1, 2, 3}, error));
  EXPECT_NE(error.find("not a SPIR-V module"), std::string::npos) << error;
  // An instruction longer than what is left of the module.
  const Words header = {0x07230203u, 0x00010300u, 0u, 10u, 0u};
  Words overrun = header;
  overrun.push_back((4u << 16) | 17u);  // OpCapability, said to be 4 words, 1 present
  EXPECT_FALSE(spirv::instructionIds(overrun, error));
  EXPECT_NE(error.find("runs past the end"), std::string::npos) << error;
  // A result ID not below the bound.
  Words outOfBound = header;
  outOfBound.insert(outOfBound.end(), {(2u << 16) | 19u, 12u});  // OpTypeVoid %12, bound 10
  EXPECT_FALSE(spirv::instructionIds(outOfBound, error));
  EXPECT_NE(error.find("not below the bound"), std::string::npos) << error;
  // OpCopyMemory: its second memory operand's IDs cannot be told from the table.
  Words copy = header;
  copy.insert(copy.end(), {(3u << 16) | 63u, 1u, 2u});
  EXPECT_FALSE(spirv::instructionIds(copy, error));
  EXPECT_NE(error.find("opcode 63"), std::string::npos) << error;
}

}  // namespace
}  // namespace mxc::test
