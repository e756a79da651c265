#pragma once
/// \file
/// What `mxc compile` writes beside a material's SPIR-V for a host renderer: the interface JSON
/// (compiler/glsl/ShaderInterface.h) as OUT.json and, for a raster shader, the vertex stage as
/// OUT.vert.spv; with --tables DIR, the albedo tables the shaders sample, once per run.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/OutputSet.h"
#include "compiler/glsl/ShaderBuilder.h"

namespace mxc::cli {

/// The interface's path beside the SPIR-V at `spirv`: x.spv -> x.json.
std::filesystem::path interfacePath(const std::filesystem::path& spirv);
/// The vertex stage's path beside the SPIR-V at `spirv`: x.spv -> x.vert.spv.
std::filesystem::path vertexPath(const std::filesystem::path& spirv);

/// Declares the interface (and the vertex stage of a raster shader) beside `spirv`.
std::optional<std::string> declareInterfaceOutputs(OutputSet& outputs, const std::filesystem::path& spirv,
                                                   glsl::ShaderKind kind);

/// The vertex stage, compiled once for the run (it is the same for every material).
const std::vector<uint32_t>& vertexStageSpirv();

/// Stages the interface of `shader` (and the vertex stage) beside `spirv`; `tables` is the
/// --tables file, or empty.
std::optional<std::string> stageInterfaceOutputs(OutputSet& outputs, const std::filesystem::path& spirv,
                                                 const ir::Material& material, const glsl::MaterialShader& shader,
                                                 glsl::ShaderKind kind, const std::filesystem::path& tables,
                                                 const std::filesystem::path& documentFolder);

/// Declares DIR/mxc_albedo_tables.bin (creating DIR); the file's path, or nullopt with `error`.
std::optional<std::filesystem::path> declareTables(OutputSet& outputs, const std::string& folder, std::string& error);
std::optional<std::string> stageTables(OutputSet& outputs, const std::filesystem::path& tables);

}  // namespace mxc::cli
