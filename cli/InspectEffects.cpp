// `mxc inspect --effects DOC|SCENE`: per material, each effect kept or dropped and why, under
// the scene (a scene file's lights and environment, or `mxc render`'s default scene for a
// document). The choices are the compiler's own (compiler/driver/Effects.h).

#include <cstdio>
#include <set>

#include <fmt/format.h>

#include "cli/ExitCode.h"
#include "cli/InspectCommand.h"
#include "cli/OutputSet.h"
#include "cli/SceneDocuments.h"
#include "compiler/common/JsonText.h"
#include "compiler/driver/Effects.h"

namespace mxc::cli {

namespace {

SceneFacts sceneFacts(const Scene& scene) {
  SceneFacts facts;
  facts.description = fmt::format("scene {}", scene.file.string());
  facts.environment = rt::environmentCode(scene.environment.kind);
  facts.environmentImage = scene.environment.image.filename().string();
  for (const rt::Light& light : scene.lights) facts.lights[static_cast<size_t>(rt::lightCode(light.kind))] += 1;
  return facts;
}

}  // namespace

int runInspectEffects(const InspectOptions& options) {
  const std::string output = options.output.empty() ? "-" : options.output;
  OutputSet outputs;
  if (printError(outputs.declare(output, "-o"))) return kOutputFailed;
  Session session;
  MaterialOptions materialOptions = options.inputs;
  materialOptions.libraries = options.libraries;
  std::vector<MaterialEffects> report;
  SceneFacts facts;
  Accuracy accuracy = materialOptions.accuracy;
  // Kept alive while the report refers to their materials.
  std::unique_ptr<SceneDocuments> documents;
  std::unique_ptr<MaterialPipeline> pipeline;
  if (isSceneFile(options.file)) {
    auto read = readScene(options.file);
    if (auto* why = std::get_if<std::string>(&read)) {
      std::fprintf(stderr, "%s\n", why->c_str());
      return kInvalidDocument;
    }
    const Scene scene = std::move(std::get<Scene>(read));
    facts = sceneFacts(scene);
    facts.specialize = !materialOptions.noSpecialize;
    if (scene.accuracy) accuracy = *scene.accuracy;
    documents = std::make_unique<SceneDocuments>(session);
    if (int code = documents->load(scene, materialOptions, glsl::ShaderKind::Raster, false); code != kOk) return code;
    // The materials the scene's objects use, in the order the objects name them.
    std::vector<std::string> names;
    for (const SceneObjectSpec& object : scene.objects) {
      if (!object.material.empty()) names.push_back(object.material);
    }
    if (!scene.look.empty()) {
      documents->forEachAssign(scene.look, [&](const doc::MaterialAssign& a) { names.emplace_back(a.material); });
    }
    std::set<const ir::Material*> seen;
    for (const std::string& name : names) {
      auto found = documents->find(name);
      if (auto* why = std::get_if<std::string>(&found)) {
        std::fprintf(stderr, "%s: %s\n", options.file.c_str(), why->c_str());
        return kInvalidDocument;
      }
      const SceneDocuments::Found& f = std::get<SceneDocuments::Found>(found);
      if (!seen.insert(f.material).second) continue;
      const glsl::MaterialInterface shader = f.pipeline->compiler().shader(*f.material).interface;
      report.push_back({f.material, materialEffects(*f.material, shader, facts, accuracy)});
    }
  } else {
    facts = SceneFacts::renderDefault();
    facts.specialize = !materialOptions.noSpecialize;
    pipeline = std::make_unique<MaterialPipeline>(session);
    CompileRequest request;
    request.document = options.file;
    if (int code = pipeline->run(request, materialOptions); code != kOk) return code;
    for (const ir::Material& m : pipeline->materials()) {
      const glsl::MaterialInterface shader = pipeline->compiler().shader(m).interface;
      report.push_back({&m, materialEffects(m, shader, facts, accuracy)});
    }
  }
  bool lossy = false;
  std::string text = options.json ? jsonText(effectsJson(report, facts), 2, &lossy) + "\n" : effectsText(report, facts);
  if (lossy) std::fprintf(stderr, "warning: %s\n", notUtf8Warning("the JSON report").c_str());
  if (printError(session.checkOutputsAreNotSources(outputs))) return kUsage;
  if (printError(outputs.stage(output, std::move(text)))) return kOutputFailed;
  if (printError(outputs.commit())) return kOutputFailed;
  return kOk;
}

}  // namespace mxc::cli
