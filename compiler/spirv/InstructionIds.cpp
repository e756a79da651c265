#include "compiler/spirv/InstructionIds.h"

#include <unordered_set>

#include <fmt/format.h>
#include <glslang/SPIRV/doc.h>
#include <glslang/SPIRV/spirv.hpp>

// The physical layout is the SPIR-V specification's, section 2.3; the operands of each
// instruction are those of section 3.49 (Instructions), as glslang's doc.cpp tabulates them.

namespace mxc::spirv {
namespace {

/// One opcode of glslang's table: its operand classes are kGrammarOperandClasses[first, first + count).
struct GrammarEntry {
  uint16_t first;
  uint8_t count;
  bool known;
  bool hasType;
  bool hasResult;
};

#include "SpirvGrammar.inc"  // generated at build time by mxc-spirv-grammar (SpirvGrammarGenerator.cpp)

/// Words of a literal string starting at `at`: up to and including the word holding its nul
/// (section 2.2.1); 0 when no word in [at, end) does.
uint32_t stringWords(const uint32_t* words, uint32_t at, uint32_t end) {
  for (uint32_t w = at; w < end; ++w) {
    const uint32_t v = words[w];
    if ((v & 0xffu) == 0 || (v & 0xff00u) == 0 || (v & 0xff0000u) == 0 || (v & 0xff000000u) == 0) return w - at + 1;
  }
  return 0;
}

}  // namespace

std::string literalString(const uint32_t* words, uint32_t at, uint32_t end) {
  std::string s;
  for (uint32_t w = at; w < end; ++w) {
    for (int b = 0; b < 4; ++b) {
      const char c = static_cast<char>((words[w] >> (8 * b)) & 0xffu);
      if (c == '\0') return s;
      s += c;
    }
  }
  return s;
}

std::optional<ModuleIds> instructionIds(const std::vector<uint32_t>& module, std::string& error) {
  ModuleIds m;
  if (module.size() < 5 || module[0] != spv::MagicNumber) {
    error = "not a SPIR-V module (its header is missing or in the other byte order)";
    return std::nullopt;
  }
  m.version = module[1];
  m.generator = module[2];
  m.bound = module[3];
  m.instructions.reserve(m.bound);
  m.uses.reserve(size_t(m.bound) * 3);
  std::unordered_set<uint32_t> glslStd450;  // IDs of OpExtInstImport "GLSL.std.450"
  bool intWidthAbove32 = false;             // an integer type wider than 32 bits was declared
  const uint32_t* words = module.data();
  const uint32_t size = uint32_t(module.size());
  for (uint32_t at = 5; at < size;) {
    const uint32_t count = words[at] >> 16;
    const uint32_t opcode = words[at] & 0xffffu;
    if (count == 0 || at + count > size) {
      error = fmt::format("the instruction at word {} runs past the end of the module", at);
      return std::nullopt;
    }
    InstructionIds inst;
    inst.at = at;
    inst.count = uint16_t(count);
    inst.opcode = uint16_t(opcode);
    inst.firstUse = uint32_t(m.uses.size());
    const uint32_t end = at + count;
    uint32_t w = at + 1;  // the next word to classify
    bool bad = false;
    auto use = [&](uint32_t word) {
      if (word >= end) return;
      if (words[word] >= m.bound || words[word] == 0) bad = true;
      m.uses.push_back(uint16_t(word - at));
      ++inst.useCount;
    };
    auto useRest = [&] {
      while (w < end) use(w++);
    };
    if (opcode > kGrammarLastOpcode || !kGrammar[opcode].known) {
      error = fmt::format("the module has an instruction the cut does not know (opcode {})", opcode);
      return std::nullopt;
    }
    const GrammarEntry& grammar = kGrammar[opcode];
    if (grammar.hasType && w < end) use(w++);
    if (grammar.hasResult && w < end) {
      if (words[w] >= m.bound || words[w] == 0) bad = true;
      inst.resultAt = uint16_t(w - at);
      ++w;
    }
    auto refuse = [&](std::string_view why) {
      error = fmt::format("the module has an instruction whose IDs the cut cannot tell (opcode {}: {})", opcode, why);
    };
    switch (static_cast<spv::Op>(opcode)) {
      case spv::OpCopyMemory:
      case spv::OpCopyMemorySized:
        refuse("two memory operands");
        return std::nullopt;
      case spv::OpSwitch:
        if (intWidthAbove32) {
          refuse("case literals may be wider than a word");
          return std::nullopt;
        }
        break;
      case spv::OpSpecConstantOp:
        if (w < end && (words[w] == spv::OpCompositeExtract || words[w] == spv::OpCompositeInsert ||
                        words[w] == spv::OpVectorShuffle)) {
          refuse("an operation with literal operands");
          return std::nullopt;
        }
        break;
      case spv::OpExtInstImport:
        if (literalString(words, w, end) == "GLSL.std.450") glslStd450.insert(words[at + 1]);
        break;
      case spv::OpExtInst:
        if (w < end && !glslStd450.count(words[w])) {
          refuse("an instruction set other than GLSL.std.450");
          return std::nullopt;
        }
        break;
      case spv::OpTypeInt:
        if (count > 2 && words[at + 2] > 32) intWidthAbove32 = true;
        break;
      default: break;
    }
    const unsigned char* classes = kGrammarOperandClasses + grammar.first;
    for (int k = 0; k < grammar.count && w < end; ++k) {
      switch (static_cast<spv::OperandClass>(classes[k])) {
        case spv::OperandId:
        case spv::OperandScope:
        case spv::OperandMemorySemantics: use(w++); break;
        case spv::OperandVariableIds: useRest(); break;
        case spv::OperandImageOperands:  // the mask, then IDs (section 3.14: every operand it adds is an ID)
          ++w;
          useRest();
          break;
        case spv::OperandMemoryAccess: {  // the mask; Aligned's literal first, the scopes it adds after are IDs
          const uint32_t mask = words[w++];
          if ((mask & spv::MemoryAccessAlignedMask) && w < end) ++w;
          useRest();
          break;
        }
        case spv::OperandVariableIdLiteral:
          while (w < end) {
            use(w++);
            if (w < end) ++w;
          }
          break;
        case spv::OperandVariableLiteralId:
          while (w < end) {
            ++w;
            if (w < end) use(w++);
          }
          break;
        case spv::OperandLiteralNumber:
          ++w;
          // OpExtInst: the instruction's number, then its operands (GLSL.std.450's are all IDs).
          if (opcode == spv::OpExtInst) useRest();
          break;
        case spv::OperandLiteralString:
        case spv::OperandOptionalLiteralString: {
          const uint32_t n = stringWords(words, w, end);
          if (n == 0) {
            error = fmt::format("a literal string of the instruction at word {} has no end", at);
            return std::nullopt;
          }
          w += n;
          break;
        }
        case spv::OperandOptionalLiteral:
        case spv::OperandVariableLiterals:
        case spv::OperandVariableLiteralStrings: w = end; break;
        default: ++w; break;  // an enumerant or mask whose parameters, if any, are literals
      }
    }
    if (bad) {
      error = fmt::format("the instruction at word {} names an ID that is 0 or not below the bound {}", at, m.bound);
      return std::nullopt;
    }
    m.instructions.push_back(inst);
    at = end;
  }
  return m;
}

}  // namespace mxc::spirv
