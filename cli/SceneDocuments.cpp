#include "cli/SceneDocuments.h"

#include <algorithm>

#include <fmt/format.h>

#include "cli/ExitCode.h"

namespace mxc::cli {

int SceneDocuments::load(const Scene& scene, MaterialOptions options, glsl::ShaderKind stage, bool optimize,
                         target::Target target, ShaderCache* shaderCache) {
  options.material.clear();
  // The scene's own search paths find its documents' images too, after --search-path's.
  for (const std::filesystem::path& folder : scene.searchPaths) options.searchPaths.push_back(folder.string());
  if (scene.accuracy) options.accuracy = *scene.accuracy;
  for (const std::filesystem::path& document : scene.documents) {
    pipelines_.push_back(std::make_unique<MaterialPipeline>(session_));
    CompileRequest request;
    request.document = document;
    request.stage = stage;
    request.optimize = optimize;
    request.target = target;
    request.shaderCache = shaderCache;
    if (int code = pipelines_.back()->run(std::move(request), options); code != kOk) return code;
  }
  return kOk;
}

std::vector<MaterialPipeline*> SceneDocuments::pipelines() const {
  std::vector<MaterialPipeline*> out;
  for (const auto& pipeline : pipelines_) out.push_back(pipeline.get());
  return out;
}

std::variant<SceneDocuments::Found, std::string> SceneDocuments::find(const std::string& name) const {
  std::vector<Found> matches;
  for (const auto& pipeline : pipelines_) {
    for (const ir::Material& material : pipeline->materials()) {
      if (material.name == name) matches.push_back({pipeline.get(), &material});
    }
  }
  if (matches.size() == 1) return matches[0];
  return fmt::format("{} material named '{}'",
                     matches.empty() ? "no document of the scene has a" : "more than one document has a", name);
}

std::variant<std::vector<SceneDocuments::Found>, std::string> SceneDocuments::used(const Scene& scene) const {
  std::vector<std::string> names;
  auto use = [&](const std::string& name) {
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  };
  for (const SceneObjectSpec& object : scene.objects) use(object.material);
  if (!scene.look.empty() &&
      !forEachAssign(scene.look, [&](const doc::MaterialAssign& assign) { use(std::string(assign.material)); })) {
    return fmt::format("look: no document of the scene has a look named '{}'", scene.look);
  }
  std::vector<Found> out;
  for (const std::string& name : names) {
    auto found = find(name);
    if (auto* why = std::get_if<std::string>(&found)) return *why;
    out.push_back(std::get<Found>(found));
  }
  return out;
}

bool SceneDocuments::forEachAssign(const std::string& look,
                                   const std::function<void(const doc::MaterialAssign&)>& visit) const {
  bool found = false;
  for (const auto& pipeline : pipelines_) {
    const doc::Document* document = pipeline->compiler().document();
    if (!document) continue;
    for (const doc::Look& candidate : document->looks) {
      if (candidate.name != look) continue;
      found = true;
      for (const doc::MaterialAssign& assign : candidate.assigns) visit(assign);
    }
  }
  return found;
}

}  // namespace mxc::cli
