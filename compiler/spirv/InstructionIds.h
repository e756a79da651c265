#pragma once
/// \file
/// Which words of each instruction of a module are IDs: its result, and the IDs it uses.
///
/// The module cut (spirv/ModuleCut.h) renumbers and follows IDs and needs nothing else of an
/// operand. It read them from SPIRV-Tools' binary parser, which decodes every operand of every
/// instruction into a typed record: 7.7 M instructions per library module, a twentieth of a
/// corpus batch. This walk reads the same from glslang's own table of the SPIR-V grammar
/// (glslang/SPIRV/doc.h, the operand classes of every opcode that its disassembler follows,
/// turned into a constant table when mxc is built: SpirvGrammarGenerator.cpp),
/// about twenty times faster. Where that table cannot say which words are IDs without more
/// context than one instruction (an OpSwitch on a selector wider than 32 bits, two memory
/// operands of OpCopyMemory, OpExtInst of a set other than GLSL.std.450, an OpSpecConstantOp),
/// the module is refused and the cut says so, as for the instructions it does not handle.
/// InstructionIdsTest checks the walk against SPIRV-Tools' parser on every corpus module.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace mxc::spirv {

struct InstructionIds {
  uint32_t at = 0;        ///< index of its first word in the module
  uint16_t count = 0;     ///< words
  uint16_t opcode = 0;
  uint16_t resultAt = 0;  ///< word offset of its result ID; 0 for none
  uint32_t firstUse = 0;  ///< index of its first used ID's offset in ModuleIds::uses
  uint16_t useCount = 0;  ///< IDs it uses (its result type included)
};

struct ModuleIds {
  uint32_t version = 0, generator = 0, bound = 0;
  std::vector<InstructionIds> instructions;
  std::vector<uint16_t> uses;  ///< word offsets within their instruction, in order
};

/// The literal string in words [at, end) (section 2.2.1: UTF-8, nul-terminated, padded to a
/// word), up to its nul.
std::string literalString(const uint32_t* words, uint32_t at, uint32_t end);

/// The IDs of every instruction of `module`, each below the header's bound; nothing, saying why
/// in `error`, for a module that is not well formed or that the walk refuses (see above).
std::optional<ModuleIds> instructionIds(const std::vector<uint32_t>& module, std::string& error);

}  // namespace mxc::spirv
