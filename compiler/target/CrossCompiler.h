#pragma once
/// \file
/// SPIR-V to GLSL (OpenGL 4.5), ESSL (OpenGL ES 3.2), MSL (Metal 2.1, macOS) and HLSL (shader
/// model 6.0) with SPIRV-Cross, each resource bound where target::placeResources puts it.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "compiler/target/Target.h"

namespace mxc::target {

/// A stage in a target language.
struct Translation {
  std::string text;
  std::string entryPoint;  ///< the entry point's name in `text` ("main", MSL's "main0")
};

/// The (set, binding) of every descriptor the module declares, by SPIRV-Cross's reflection;
/// empty when the module cannot be read.
std::vector<std::pair<uint32_t, uint32_t>> descriptorBindings(const std::vector<uint32_t>& words);

/// Translates a validated module to `target` (not Spirv or Wgsl). On failure (SPIRV-Cross
/// rejects the module) returns false with SPIRV-Cross's message in `error`.
bool crossCompile(const std::vector<uint32_t>& words, Target target, const std::vector<Placement>& placements,
                  Translation& out, std::string& error);

}  // namespace mxc::target
