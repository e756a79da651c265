#pragma once
/// \file
/// Batch compilation by library: the shaders of a batch that differ only in their material's
/// closure function compile as one shader, and each material's module is cut from it.
///
/// A shader's SPIR-V compile is nearly all library (the corpus's raster shaders: about 5,000
/// instructions, of which the material's function is under a hundred), and glslang's parse
/// and SPIRV-Tools' validation of it cost about 110 M instructions per shader. The corpus's 75
/// materials are 70 distinct shaders but 18 libraries (glsl::MaterialShader::libraryKey). A
/// group is one glslang compile and one validation (glsl/ShaderGroup.h); its members' modules
/// are cut from the validated module (spirv/ModuleCut.h), the same bytes a compile of each
/// alone writes (ShaderGroupTest checks every corpus material).

#include <memory>
#include <string>
#include <vector>

#include "compiler/driver/Compiler.h"

namespace mxc {

/// The key under which compileShader keeps a shader's module in a ShaderCache: its code, the
/// stage and the options the module depends on.
std::string shaderCacheKey(const glsl::MaterialShader& shader, const CompileRequest& request);

/// Adds to `cache` a group for each library of `shaders` (the shaders a batch is about to
/// compile with `request`'s options) that has two distinct codes or more. Nothing is compiled
/// here: the first material of a group to reach compileShader compiles the group.
/// Optimised modules (-O) are not grouped: each is optimised from its own module. A group holds
/// its members (shared with the caller, not copied: a batch's shaders are megabytes of text).
void planShaderGroups(ShaderCache& cache, const std::vector<std::shared_ptr<const glsl::MaterialShader>>& shaders,
                      const CompileRequest& request);

}  // namespace mxc
