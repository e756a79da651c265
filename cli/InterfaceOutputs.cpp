#include "cli/InterfaceOutputs.h"

#include <mutex>
#include <stdexcept>

#include "compiler/common/Diagnostic.h"
#include "compiler/glsl/ShaderInterface.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::cli {

namespace fs = std::filesystem;

fs::path interfacePath(const fs::path& spirv) {
  fs::path out = spirv;
  return out.replace_extension(".json");
}

fs::path vertexPath(const fs::path& spirv) {
  fs::path out = spirv;
  return out.replace_extension(".vert.spv");
}

std::optional<std::string> declareInterfaceOutputs(OutputSet& outputs, const fs::path& spirv, glsl::ShaderKind kind) {
  if (auto why = outputs.declare(interfacePath(spirv), "-o (its interface)")) return why;
  if (kind == glsl::ShaderKind::Raster) return outputs.declare(vertexPath(spirv), "-o (its vertex stage)");
  return std::nullopt;
}

const std::vector<uint32_t>& vertexStageSpirv() {
  static std::once_flag once;
  static std::vector<uint32_t> words;
  std::call_once(once, [] {
    Diagnostics diagnostics;
    auto compiled = spirv::compile(glsl::buildVertexShader(), {}, diagnostics);
    // The vertex stage is mxc's own fixed code, compiled by every test: a failure is a bug.
    if (!compiled) throw std::logic_error("the vertex stage does not compile: " + diagnostics.format());
    words = std::move(*compiled);
  });
  return words;
}

std::optional<std::string> stageInterfaceOutputs(OutputSet& outputs, const fs::path& spirv, const ir::Material& material,
                                                 const glsl::MaterialShader& shader, glsl::ShaderKind kind,
                                                 const fs::path& tables, const fs::path& documentFolder) {
  const fs::path json = interfacePath(spirv);
  glsl::InterfaceFiles files;
  // Paths relative to the interface file, so that the folder can be moved whole.
  const fs::path folder = fs::absolute(json).parent_path();
  files.shader = spirv.filename().string();
  files.documentFolder = fs::absolute(documentFolder).lexically_normal().string();
  if (kind == glsl::ShaderKind::Raster) files.vertex = vertexPath(spirv).filename().string();
  if (!tables.empty()) files.tables = fs::absolute(tables).lexically_relative(folder).string();
  const std::string text = glsl::shaderInterfaceJson(material, shader, kind, files).dump(2) + "\n";
  if (auto why = outputs.stage(json, text)) return why;
  if (kind == glsl::ShaderKind::Raster) {
    const std::vector<uint32_t>& words = vertexStageSpirv();
    std::string bytes(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t));
    if (auto why = outputs.stage(vertexPath(spirv), std::move(bytes))) return why;
  }
  return std::nullopt;
}

std::optional<fs::path> declareTables(OutputSet& outputs, const std::string& folder, std::string& error) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) {
    error = folder + ": cannot create the folder: " + ec.message();
    return std::nullopt;
  }
  const fs::path path = fs::path(folder) / glsl::kAlbedoTablesFileName;
  if (auto why = outputs.declare(path, "--tables")) {
    error = *why;
    return std::nullopt;
  }
  return path;
}

std::optional<std::string> stageTables(OutputSet& outputs, const fs::path& tables) {
  return outputs.stage(tables, glsl::albedoTablesFile());
}

}  // namespace mxc::cli
