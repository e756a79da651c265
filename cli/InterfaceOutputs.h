#pragma once
/// \file
/// What `mxc compile` writes for one material: its shader at OUT (SPIR-V, or the --target
/// language's text made from it, compiler/target/Translate.h), and, unless OUT is standard
/// output, the interface JSON (compiler/glsl/ShaderInterface.h) as OUT.json and, for a raster
/// shader, the vertex stage in the same language as OUT.vert<ext>; with --tables DIR, the albedo
/// tables the shaders sample, once per run.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/OutputSet.h"
#include "compiler/driver/Compiler.h"
#include "compiler/glsl/ShaderBuilder.h"

namespace mxc::cli {

/// The interface's path beside the shader at `shader`: x.spv -> x.json.
std::filesystem::path interfacePath(const std::filesystem::path& shader);
/// The vertex stage's path beside the shader at `shader`: x.spv -> x.vert.spv, x.metal -> x.vert.metal.
std::filesystem::path vertexPath(const std::filesystem::path& shader);

/// Declares the interface (and the vertex stage of a raster shader) beside `shader`.
std::optional<std::string> declareInterfaceOutputs(OutputSet& outputs, const std::filesystem::path& shader,
                                                   glsl::ShaderKind kind);

/// How staging a material's outputs ended.
enum class Staged {
  Ok,
  TranslationFailed,  ///< the target's translator or check rejected a stage (reported in the compiler's diagnostics)
  OutputFailed,       ///< an output could not be staged (the message in `error`)
};

/// Stages the material's shader (`words` in the compiler's target) at `path` and, with
/// `interface`, its interface JSON and vertex stage beside it. `tables` is the --tables file, or
/// empty. `lines` receives the number of lines of a text target's shader.
Staged stageShaderOutputs(OutputSet& outputs, const std::filesystem::path& path, bool interface, Compiler& compiler,
                          const ir::Material& material, const glsl::MaterialShader& shader,
                          const std::vector<uint32_t>& words, glsl::ShaderKind kind,
                          const std::filesystem::path& tables, const std::filesystem::path& documentFolder,
                          std::string& error, size_t* lines = nullptr);

/// Declares DIR/mxc_albedo_tables.bin (creating DIR); the file's path, or nullopt with `error`.
std::optional<std::filesystem::path> declareTables(OutputSet& outputs, const std::string& folder, std::string& error);
std::optional<std::string> stageTables(OutputSet& outputs, const std::filesystem::path& tables);

}  // namespace mxc::cli
