#include "compiler/spirv/SpirvCompiler.h"

#include <functional>
#include <mutex>
#include <regex>
#include <unordered_map>

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "compiler/spirv/SourceTrim.h"

namespace mxc::spirv {

namespace {

EShLanguage language(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return EShLangVertex;
    case Stage::Fragment: return EShLangFragment;
    case Stage::Compute: return EShLangCompute;
  }
  return EShLangFragment;
}

// Functions that would be longer than this many instructions with their callees inlined stay
// functions under `-O`.
constexpr size_t kInlineLimit = 150;

/// Marks DontInline every function whose body, with the callees it would inline, exceeds
/// kInlineLimit instructions, so that SPIRV-Tools' exhaustive inlining copies only small
/// functions into their callers. A closure calls its lobe functions once per lobe (eval, pdf,
/// sample, albedo), and they call each other: inlining every call made the optimised module
/// about three times the unoptimised one. The drivers' own compilers still decide what to
/// inline on the device.
void keepLargeFunctionsAsCalls(std::vector<uint32_t>& words) {
  constexpr uint32_t kOpFunction = 54, kOpFunctionEnd = 56, kOpFunctionCall = 57;
  constexpr uint32_t kInline = 0x1, kDontInline = 0x2;
  struct Function {
    size_t control = 0;            // index of OpFunction's function-control word
    size_t length = 0;             // its own instructions
    std::vector<uint32_t> calls;   // callee ids, one per call site
  };
  std::unordered_map<uint32_t, Function> functions;
  Function* current = nullptr;
  for (size_t i = 5; i < words.size();) {  // after the 5-word header
    const uint32_t count = words[i] >> 16;
    const uint32_t opcode = words[i] & 0xffffu;
    if (count == 0 || i + count > words.size()) return;  // malformed: leave it to the validator
    if (opcode == kOpFunction && count >= 5) {
      current = &functions[words[i + 2]];  // result type, result id, function control, type
      current->control = i + 3;
    } else if (opcode == kOpFunctionEnd) {
      current = nullptr;
    } else if (current) {
      ++current->length;
      if (opcode == kOpFunctionCall && count >= 4) current->calls.push_back(words[i + 3]);
    }
    i += count;
  }
  // Size with the small callees inlined, callees first (SPIR-V forbids recursion; the depth
  // bound guards a malformed module).
  std::unordered_map<uint32_t, size_t> inlined;
  std::function<size_t(uint32_t, int)> size = [&](uint32_t id, int depth) -> size_t {
    auto known = inlined.find(id);
    if (known != inlined.end()) return known->second;
    auto f = functions.find(id);
    if (f == functions.end() || depth > 64) return 0;
    size_t total = f->second.length;
    for (uint32_t callee : f->second.calls) {
      const size_t s = size(callee, depth + 1);
      if (s <= kInlineLimit) total += s;  // inlined here; a kept function is one call
    }
    inlined[id] = total;
    if (total > kInlineLimit) {
      uint32_t& control = words[f->second.control];
      control = (control & ~kInline) | kDontInline;
    }
    return total;
  };
  for (const auto& [id, f] : functions) size(id, 0);
}

Reflection::Scalar scalarOf(const glslang::TType& type) {
  switch (type.getBasicType()) {
    case glslang::EbtFloat: return Reflection::Scalar::Float;
    case glslang::EbtInt: return Reflection::Scalar::Int;
    case glslang::EbtUint: return Reflection::Scalar::UInt;
    case glslang::EbtBool: return Reflection::Scalar::Bool;
    case glslang::EbtSampler: return Reflection::Scalar::Sampler;
    default: return Reflection::Scalar::Other;
  }
}

void reflect(glslang::TProgram& program, Reflection& out) {
  program.buildReflection(EShReflectionDefault | EShReflectionAllBlockVariables | EShReflectionUnwrapIOBlocks);
  for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
    const glslang::TObjectReflection& b = program.getUniformBlock(i);
    out.blocks.push_back({b.name, b.getBinding(), b.size});
  }
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    const glslang::TType* type = u.getType();
    if (!type) continue;
    if (type->getBasicType() == glslang::EbtSampler) {
      out.samplers.push_back({u.name, u.getBinding()});
      continue;
    }
    Reflection::Member m;
    m.name = u.name;
    m.block = u.index;
    m.offset = u.offset;
    m.scalar = scalarOf(*type);
    m.columns = type->isMatrix() ? type->getMatrixCols() : 1;
    m.components = type->isMatrix() ? type->getMatrixCols() * type->getMatrixRows() : std::max(1, type->getVectorSize());
    m.arraySize = std::max(1, u.size);
    m.arrayStride = u.arrayStride;
    out.members.push_back(m);
  }
  for (int i = 0; i < program.getNumPipeInputs(); ++i) {
    const glslang::TObjectReflection& in = program.getPipeInput(i);
    const glslang::TType* type = in.getType();
    if (!type) continue;
    const int location = type->getQualifier().hasLocation() ? static_cast<int>(type->getQualifier().layoutLocation) : -1;
    out.inputs.push_back({in.name, location, std::max(1, type->getVectorSize())});
  }
}

/// glslang's process-wide state is initialised once (it is reference counted, never finalised
/// here: the process ends first).
void initialise() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

/// Sets `shader` up as mxc compiles for Vulkan 1.1 / SPIR-V 1.3 from `source` (GLSL, or the
/// HLSL a translator wrote); the messages that go with it.
EShMessages forVulkan(glslang::TShader& shader, glslang::EShSource source, EShLanguage stage) {
  shader.setEnvInput(source, stage, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  return static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
}

/// The linked program's stage as SPIR-V, glslang's own optimiser off (SPIRV-Tools' runs when
/// asked for); empty, with glslang's messages in `problems`, when it generates none.
std::vector<uint32_t> generate(const glslang::TProgram& program, EShLanguage stage, std::string& problems) {
  std::vector<uint32_t> words;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.disableOptimizer = true;
  glslang::GlslangToSpv(*program.getIntermediate(stage), words, &logger, &options);
  problems = logger.getAllMessages();
  return words;
}

/// Maps glslang's "ERROR: 0:LINE: message" lines to diagnostics at the generated line's origin.
void reportLog(const GlslSource& source, const std::string& log, Diagnostics& diagnostics) {
  static const std::regex line(R"((ERROR|WARNING): (?:\d+|[^:]*):(\d+): (.*))");
  bool reported = false;
  size_t start = 0;
  while (start < log.size()) {
    size_t end = log.find('\n', start);
    if (end == std::string::npos) end = log.size();
    std::string text = log.substr(start, end - start);
    start = end + 1;
    std::smatch m;
    if (!std::regex_match(text, m, line) || m[1] != "ERROR") continue;
    const size_t number = std::stoul(m[2]);
    SourceLocation where = number >= 1 && number <= source.origins.size() ? source.origins[number - 1] : SourceLocation{};
    diagnostics.error(where, fmt::format("GLSL for {} does not compile (generated line {}): {}", source.name, number,
                                         m[3].str()));
    reported = true;
  }
  if (!reported && !log.empty()) diagnostics.error({}, fmt::format("GLSL for {} does not compile: {}", source.name, log));
}

}  // namespace

std::string_view stageName(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return "vertex";
    case Stage::Fragment: return "fragment";
    case Stage::Compute: return "compute";
  }
  return "?";
}

std::optional<std::vector<uint32_t>> compile(const GlslSource& source, const CompileOptions& options,
                                             Diagnostics& diagnostics) {
  initialise();
  const EShLanguage stage = language(source.stage);
  glslang::TShader shader(stage);
  // glslang reads the text without what cannot reach the SPIR-V (comments, branches not taken,
  // functions nothing calls); its lines are those of source.text, for the messages.
  const std::string parsed = options.trimSource ? trimForParse(source.text).text : std::string();
  const char* text = options.trimSource ? parsed.c_str() : source.text.c_str();
  shader.setStrings(&text, 1);
  const EShMessages messages = forVulkan(shader, glslang::EShSourceGlsl, stage);
  if (!shader.parse(GetDefaultResources(), 450, false, messages)) {
    reportLog(source, shader.getInfoLog(), diagnostics);
    return std::nullopt;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    reportLog(source, program.getInfoLog(), diagnostics);
    return std::nullopt;
  }
  if (options.reflection) reflect(program, *options.reflection);
  std::string problems;
  std::vector<uint32_t> words = generate(program, stage, problems);
  if (words.empty()) {
    diagnostics.error({}, fmt::format("SPIR-V generation for {} failed: {}", source.name, problems));
    return std::nullopt;
  }
  if (options.optimize) {
    keepLargeFunctionsAsCalls(words);
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_1);
    if (!options.specialization.empty()) {
      std::unordered_map<uint32_t, std::string> values;
      for (const auto& [id, value] : options.specialization) values[id] = std::to_string(value);
      optimizer.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(values));
      optimizer.RegisterPass(spvtools::CreateFreezeSpecConstantValuePass());
      // Expressions of the constants (OpSpecConstantOp: `MXC_LIGHT_COUNT > 0`) become constants.
      optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
    }
    optimizer.RegisterPerformancePasses();
    std::vector<uint32_t> optimized;
    if (optimizer.Run(words.data(), words.size(), &optimized)) words = std::move(optimized);
  }
  if (std::string error = validate(words); !error.empty()) {
    diagnostics.error({}, fmt::format("the SPIR-V of {} is not valid: {}", source.name, error));
    return std::nullopt;
  }
  return words;
}

std::string validate(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
  std::string message;
  tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& position, const char* text) {
    message += fmt::format("{}{}", message.empty() ? "" : "; ", text);
    (void)position;
  });
  // Friendly names (%float for %12 in messages) cost a third of a material's compile time:
  // SPIRV-Tools builds them for the whole module before validating, for messages a valid module
  // never prints. Validate without them; only a module that fails is validated again with them,
  // so its message names what it is about.
  spvtools::ValidatorOptions quick;
  quick.SetFriendlyNames(false);
  if (tools.Validate(words.data(), words.size(), quick)) return {};
  message.clear();
  tools.Validate(words);  // fails again, now with the names in its message
  return message.empty() ? "invalid module" : message;
}

std::optional<std::vector<uint32_t>> freezeSpecialization(const std::vector<uint32_t>& words, std::string& error) {
  spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_1);
  optimizer.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t&, const char* text) {
    error += (error.empty() ? "" : "; ") + std::string(text);
  });
  optimizer.RegisterPass(spvtools::CreateFreezeSpecConstantValuePass());
  // Expressions of the constants (OpSpecConstantOp: `MXC_LIGHT_COUNT != -1`) become constants.
  optimizer.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
  std::vector<uint32_t> out;
  if (!optimizer.Run(words.data(), words.size(), &out)) {
    if (error.empty()) error = "SPIRV-Tools cannot fix the specialization constants";
    return std::nullopt;
  }
  error.clear();
  return out;
}

std::string checkSource(const std::string& text, Language dialect, Stage stage, const std::string& entryPoint) {
  initialise();
  const EShLanguage shaderStage = language(stage);
  glslang::TShader shader(shaderStage);
  const char* source = text.c_str();
  shader.setStrings(&source, 1);
  EShMessages messages = EShMsgDefault;
  if (dialect == Language::Hlsl) {
    messages = static_cast<EShMessages>(forVulkan(shader, glslang::EShSourceHlsl, shaderStage) | EShMsgReadHlsl);
    shader.setEntryPoint(entryPoint.c_str());
  } else {
    // An OpenGL driver's compiler: no SPIR-V, the version and profile from the #version line.
    shader.setEnvInput(glslang::EShSourceGlsl, shaderStage, glslang::EShClientNone, 0);
  }
  const int defaultVersion = dialect == Language::OpenGlEs ? 320 : 450;
  if (!shader.parse(GetDefaultResources(), defaultVersion, false, messages)) return shader.getInfoLog();
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) return program.getInfoLog();
  if (dialect != Language::Hlsl) return {};
  std::string problems;
  const std::vector<uint32_t> words = generate(program, shaderStage, problems);
  if (words.empty()) return "no SPIR-V generated: " + problems;
  return validate(words);
}

size_t instructionCount(const std::vector<uint32_t>& words) {
  size_t count = 0;
  for (size_t i = 5; i < words.size();) {
    const uint32_t wordCount = words[i] >> 16;
    if (wordCount == 0) break;  // malformed: stop rather than loop
    ++count;
    i += wordCount;
  }
  return count;
}

std::string disassemble(const std::vector<uint32_t>& words) {
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
  std::string text;
  tools.Disassemble(words, &text, SPV_BINARY_TO_TEXT_OPTION_INDENT | SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES);
  return text;
}

}  // namespace mxc::spirv
