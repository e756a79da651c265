#pragma once
/// \file
/// A stage of a material in a target language (compiler/target/Target.h), validated by that
/// language's own toolchain where one runs here: glslang's front ends for GLSL, ESSL and HLSL
/// (HLSL compiled to SPIR-V and validated), naga's validator for WGSL. MSL has no compiler off
/// Apple's platforms: SPIRV-Cross's own checks are all it gets.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "compiler/spirv/SpirvCompiler.h"
#include "compiler/target/CrossCompiler.h"
#include "compiler/target/Target.h"

namespace mxc::target {

/// Translates `words` (a validated module of `stage`) to `target`, not Spirv; nullopt (and
/// `error`) when the translator or the check rejects it.
std::optional<Translation> translate(const std::vector<uint32_t>& words, spirv::Stage stage, Target target,
                                     const std::vector<Placement>& placements, std::string& error);

}  // namespace mxc::target
