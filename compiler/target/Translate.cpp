#include "compiler/target/Translate.h"

#include <fmt/format.h>

#include "compiler/target/NagaTranslator.h"

namespace mxc::target {

std::optional<Translation> translate(const std::vector<uint32_t>& words, spirv::Stage stage, Target target,
                                     const std::vector<Placement>& placements, std::string& error) {
  Translation out;
  switch (target) {
    case Target::Spirv:
      error = "SPIR-V is not translated";
      return std::nullopt;
    case Target::Wgsl:
      if (!nagaTranslate(words, out, error)) return std::nullopt;
      return out;
    case Target::Glsl:
    case Target::Essl:
    case Target::Msl:
    case Target::Hlsl:
      if (!crossCompile(words, target, placements, out, error)) return std::nullopt;
      break;
  }
  if (target == Target::Msl) return out;
  const spirv::Language language = target == Target::Glsl   ? spirv::Language::OpenGl
                                   : target == Target::Essl ? spirv::Language::OpenGlEs
                                                            : spirv::Language::Hlsl;
  if (std::string log = spirv::checkSource(out.text, language, stage, out.entryPoint); !log.empty()) {
    error = fmt::format("the {} SPIRV-Cross wrote does not compile: {}", targetName(target), log);
    return std::nullopt;
  }
  return out;
}

}  // namespace mxc::target
