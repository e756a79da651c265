#include "cli/InterfaceOutputs.h"

#include <cstdio>
#include <algorithm>
#include <map>
#include <mutex>
#include <utility>

#include <fmt/format.h>

#include "compiler/common/Quote.h"
#include "compiler/common/JsonText.h"
#include "compiler/common/Diagnostic.h"
#include "compiler/glsl/ShaderInterface.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "compiler/target/CrossCompiler.h"
#include "compiler/target/Target.h"

namespace mxc::cli {

namespace fs = std::filesystem;

fs::path interfacePath(const fs::path& shader) {
  fs::path out = shader;
  return out.replace_extension(".json");
}

fs::path vertexPath(const fs::path& shader) {
  fs::path out = shader;
  return out.replace_extension(".vert" + shader.extension().string());
}

std::optional<std::string> declareInterfaceOutputs(OutputSet& outputs, const fs::path& shader, glsl::ShaderKind kind) {
  if (auto why = outputs.declare(interfacePath(shader), "-o (its interface)")) return why;
  if (kind == glsl::ShaderKind::Raster) return outputs.declare(vertexPath(shader), "-o (its vertex stage)");
  return std::nullopt;
}

namespace {

std::string bytesOf(const std::vector<uint32_t>& words) {
  return std::string(reinterpret_cast<const char*>(words.data()), words.size() * sizeof(uint32_t));
}

/// The vertex stage in the compiler's target, its descriptors where `placements` puts them. The
/// module is the same for every material and binds only the view block, which every material of
/// a target places alike: it is translated and checked once per run for each placement of its own
/// descriptors, not once per material of a batch (for WGSL, two runs of naga each).
std::optional<target::Translation> vertexStageIn(Compiler& compiler, const std::vector<target::Placement>& placements) {
  static const std::vector<std::pair<uint32_t, uint32_t>> bound = target::descriptorBindings(glsl::vertexStageSpirv());
  const target::Target target = compiler.request().target;
  std::vector<target::Placement> own;
  std::string key(target::targetName(target));
  for (const target::Placement& p : placements) {
    if (std::find(bound.begin(), bound.end(), std::pair(p.resource.set, p.resource.binding)) == bound.end()) continue;
    own.push_back(p);
    key += fmt::format(" {}.{}={}", p.resource.set, p.resource.binding, jsonText(target::placementJson(p, target), -1));
  }
  static std::mutex mutex;  // batch workers
  static std::map<std::string, target::Translation> translated;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (auto found = translated.find(key); found != translated.end()) return found->second;
  }
  std::optional<target::Translation> vertex = compiler.translate(glsl::vertexStageSpirv(), spirv::Stage::Vertex, own, "the vertex stage");
  if (vertex) {
    const std::lock_guard<std::mutex> lock(mutex);
    translated.emplace(key, *vertex);
  }
  return vertex;
}

/// The interface JSON told which language its stages are in and where that language binds each
/// descriptor (docs/shader-interface.md, "Targets").
void describeTarget(nlohmann::json& interface, target::Target target, const std::vector<target::Placement>& placements,
                    const std::string& fragmentEntry, const std::string& vertexEntry) {
  interface["target"] = std::string(target::targetName(target));
  for (auto& [name, stage] : interface["stages"].items()) {
    stage["entryPoint"] = name == "vertex" ? vertexEntry : fragmentEntry;
    if (target != target::Target::Spirv) stage.erase("spirv");  // "file" names the target's text
  }
  if (target == target::Target::Spirv) return;
  for (size_t i = 0; i < placements.size() && i < interface["descriptors"].size(); ++i) {
    interface["descriptors"][i]["target"] = target::placementJson(placements[i], target);
  }
  // naga reads no specialization: the WGSL has the defaults, which read the values from MxcView.
  if (target == target::Target::Wgsl && interface.contains("specializationConstants")) {
    interface["specializationConstants"] = nlohmann::json::array();
  }
}

}  // namespace

Staged stageShaderOutputs(OutputSet& outputs, const fs::path& path, bool interface, Compiler& compiler,
                          const ir::Material& material, const glsl::MaterialShader& shader,
                          const std::vector<uint32_t>& words, glsl::ShaderKind kind, const fs::path& tables,
                          const fs::path& documentFolder, std::string& error, size_t* lines) {
  const target::Target target = compiler.request().target;
  const bool raster = kind == glsl::ShaderKind::Raster;
  glsl::InterfaceFiles files;
  const fs::path json = interfacePath(path);
  // Paths relative to the interface file, so that the folder can be moved whole.
  const fs::path folder = fs::absolute(json).parent_path();
  files.shader = path.filename().string();
  files.documentFolder = fs::absolute(documentFolder).lexically_normal().string();
  if (raster) files.vertex = vertexPath(path).filename().string();
  if (!tables.empty()) files.tables = fs::absolute(tables).lexically_relative(folder).string();
  nlohmann::json description = glsl::shaderInterfaceJson(material, shader, kind, files);

  std::string text = bytesOf(words), vertexText;
  std::string fragmentEntry = "main", vertexEntry = "main";
  std::vector<target::Placement> placements;
  if (target != target::Target::Spirv) {
    // One placement of the descriptors for both stages, so that they agree.
    placements = target::placeResources(target::resourcesOfInterface(description), target);
    const spirv::Stage stage = raster ? spirv::Stage::Fragment : spirv::Stage::Compute;
    auto translated = compiler.translate(words, stage, placements,
                                         fmt::format("material {} ({})", material.name, spirv::stageName(stage)));
    if (!translated) return Staged::TranslationFailed;
    text = std::move(translated->text);
    fragmentEntry = translated->entryPoint;
    if (lines) *lines = static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
    if (interface && raster) {
      auto vertex = vertexStageIn(compiler, placements);
      if (!vertex) return Staged::TranslationFailed;
      vertexText = std::move(vertex->text);
      vertexEntry = vertex->entryPoint;
    }
  } else if (interface && raster) {
    vertexText = bytesOf(glsl::vertexStageSpirv());
  }
  if (auto why = outputs.stage(path, std::move(text))) return error = *why, Staged::OutputFailed;
  if (!interface) return Staged::Ok;
  describeTarget(description, target, placements, fragmentEntry, vertexEntry);
  bool lossy = false;
  std::string jsonContent = jsonText(description, 2, &lossy) + "\n";
  if (lossy) std::fprintf(stderr, "warning: %s\n", notUtf8Warning(quotedValue(json.string())).c_str());
  if (auto why = outputs.stage(json, std::move(jsonContent))) return error = *why, Staged::OutputFailed;
  if (raster) {
    if (auto why = outputs.stage(vertexPath(path), std::move(vertexText))) return error = *why, Staged::OutputFailed;
  }
  return Staged::Ok;
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
