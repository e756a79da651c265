// `mxc render SCENE.json`: every object of a scene file in one image (cli/Scene.h).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <set>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "cli/Verbosity.h"
#include "cli/ExitCode.h"
#include "cli/Harness.h"
#include "cli/MaterialPipeline.h"
#include "cli/MeshArgument.h"
#include "cli/OutputSet.h"
#include "cli/RenderCommand.h"
#include "cli/RenderOutput.h"
#include "cli/Scene.h"
#include "cli/SceneDocuments.h"
#include "cli/SearchPaths.h"
#include "compiler/document/Document.h"
#include "runtime/EnvironmentMap.h"
#include "runtime/Renderer.h"

namespace mxc::cli {

namespace {

/// The sphere about every object in the world: the bounding box of the objects' spheres, then
/// the farthest of their surfaces from its centre.
rt::MeshBounds worldBounds(const std::vector<rt::MeshBounds>& spheres) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const rt::MeshBounds& b : spheres) {
    lo = glm::min(lo, b.center - b.radius);
    hi = glm::max(hi, b.center + b.radius);
  }
  rt::MeshBounds all;
  all.center = 0.5f * (lo + hi);
  for (const rt::MeshBounds& b : spheres) all.radius = std::max(all.radius, glm::length(b.center - all.center) + b.radius);
  return all;
}

/// An object's bounding sphere under its transform: the centre moved, the radius scaled by the
/// transform's largest axis scale (an upper bound under any rotation and shear).
rt::MeshBounds transformed(const rt::MeshBounds& b, const glm::mat4& m) {
  const float scale = std::max({glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
  return {glm::vec3(m * glm::vec4(b.center, 1.0f)), b.radius * scale};
}

/// "a, /b ,c" to {"a", "b", "c"}: MaterialX geometry names, the leading '/' of a path dropped.
std::vector<std::string> geomNames(std::string_view geom) {
  std::vector<std::string> names;
  size_t start = 0;
  while (start <= geom.size()) {
    const size_t comma = std::min(geom.find(',', start), geom.size());
    std::string name(geom.substr(start, comma - start));
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    if (!name.empty() && name[0] == '/') name.erase(0, 1);
    if (!name.empty()) names.push_back(name);
    start = comma + 1;
  }
  return names;
}

}  // namespace

int runSceneRender(const RenderOptions& options) {
  auto given = [&](const char* option) {
    return std::find(options.explicitOptions.begin(), options.explicitOptions.end(), option) != options.explicitOptions.end();
  };
  // The scene states its meshes, camera, lights and environment; the command line may only
  // change the image's size, samples, exposure and tone curve.
  for (const char* option : {"--mesh", "--camera-position", "--camera-target", "--camera-up", "--fov", "--light", "--env",
                             "--env-intensity", "--env-rotation", "--background", "--material", "--look"}) {
    if (given(option)) {
      std::fprintf(stderr, "error: %s cannot be used with a scene file: the scene states it\n", option);
      return kUsage;
    }
  }
  auto read = readScene(options.file);
  if (auto* why = std::get_if<std::string>(&read)) {
    std::fprintf(stderr, "%s\n", why->c_str());
    return kInvalidDocument;
  }
  Scene scene = std::move(std::get<Scene>(read));
  if (given("--size") && !parseRenderSize(options.size, scene.width, scene.height)) {
    std::fprintf(stderr, "error: --size %s: expected N or WxH, each from 8 to 8192\n", options.size.c_str());
    return kUsage;
  }
  if (given("--spp")) scene.spp = static_cast<uint32_t>(options.spp);
  if (given("--exposure")) scene.exposure = options.exposure;
  if (given("--tonemap")) scene.toneMapping = options.toneMapping;
  return renderSceneData(scene, options, {});
}

int renderSceneData(const Scene& scene, const RenderOptions& options, std::map<std::string, MeshChoice> meshes) {
  // What messages name: the scene file, or the document of a scene made from the command line.
  const std::string source = scene.file.empty() ? options.file : scene.file.string();
  rt::RenderSettings settings;
  settings.width = scene.width;
  settings.height = scene.height;
  settings.frames = scene.spp;
  settings.specialize = !options.materials.noSpecialize;
  const float exposure = scene.exposure;
  const rt::ToneMapping tone = rt::parseToneMapping(scene.toneMapping).value_or(rt::ToneMapping::AcesFit);
  settings.environment = scene.environment.kind;
  settings.environmentIntensity = scene.environment.intensity;
  settings.environmentRotation = scene.environment.rotationDegrees;
  settings.emissionScale = options.emissionScale;
  settings.lights = scene.lights;


  // Meshes, each file read once however many objects use it.
  std::vector<std::filesystem::path> paths = scene.searchPaths;
  for (const auto& p : searchPaths(options.materials.searchPaths)) paths.push_back(p);
  std::vector<rt::MeshBounds> spheres;
  for (const SceneObjectSpec& object : scene.objects) {
    if (!meshes.count(object.mesh)) {
      auto chosen = chooseMesh(object.mesh, paths);
      if (auto* why = std::get_if<std::string>(&chosen)) {
        std::fprintf(stderr, "%s: error: object '%s': %s\n", source.c_str(), object.name.c_str(), why->c_str());
        return kInvalidDocument;
      }
      meshes.emplace(object.mesh, std::move(std::get<MeshChoice>(chosen)));
    }
    spheres.push_back(transformed(rt::meshBounds(meshes.at(object.mesh).mesh), object.objectToWorld));
  }
  const rt::MeshBounds bounds = worldBounds(spheres);
  if (scene.camera) {
    settings.camera = *scene.camera;
    rt::fitClipPlanes(settings.camera, bounds);
  } else {
    // From the front and a little above, so that a floor is seen rather than its edge.
    settings.camera = rt::frameBounds(bounds, scene.viewDirection, 45.0f, float(settings.width) / float(settings.height));
  }
  if (auto why = rt::scaleProblem(bounds, settings.camera)) {
    std::fprintf(stderr, "%s: error: %s\n", source.c_str(), why->c_str());
    return kInvalidDocument;
  }

  // Documents, and each object's material: its own, else its document's look.
  Session session;
  SceneDocuments documents(session);
  if (int code = documents.load(scene, options.materials, glsl::ShaderKind::Raster, false); code != kOk) return code;
  // The look's assignments, by geometry name (an object's, or a part's of its mesh); the last
  // assignment of a name wins, as later elements of a document do; "*" or no geom: anything.
  std::map<std::string, std::string> assignedTo;
  std::string assignedToAll;
  if (!scene.look.empty() && !documents.forEachAssign(scene.look, [&](const doc::MaterialAssign& assign) {
        const std::vector<std::string> names = geomNames(assign.geom);
        if (assign.geom.empty() || std::find(names.begin(), names.end(), "*") != names.end()) {
          assignedToAll = std::string(assign.material);
        }
        for (const std::string& name : names) assignedTo[name] = std::string(assign.material);
      })) {
    std::fprintf(stderr, "%s: error: look: no document of the scene has a look named '%s'\n", source.c_str(),
                 scene.look.c_str());
    return kInvalidDocument;
  }
  auto lookMaterial = [&](const std::string& name) {
    auto it = assignedTo.find(name);
    return it != assignedTo.end() ? it->second : assignedToAll;
  };
  // The draws: an object with its own material is one draw; otherwise, when the look assigns
  // parts of its mesh, one draw per part; otherwise the look's material for the object.
  struct Draw {
    size_t object;
    std::string material;
    std::string what;  ///< "objects[1] ('ball')", with " part 'Preview_Mesh'"
    uint32_t firstIndex = 0, indexCount = 0;
  };
  std::vector<Draw> draws;
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObjectSpec& object = scene.objects[o];
    const std::string what = fmt::format("objects[{}] ('{}')", o, object.name);
    const rt::Mesh& mesh = meshes.at(object.mesh).mesh;
    const bool byParts = object.material.empty() &&
                         std::any_of(mesh.parts.begin(), mesh.parts.end(), [&](const rt::MeshPart& p) { return assignedTo.count(p.name) > 0; });
    if (!byParts) {
      draws.push_back({o, object.material.empty() ? lookMaterial(object.name) : object.material, what});
      continue;
    }
    for (const rt::MeshPart& part : mesh.parts) {
      const std::string material = assignedTo.count(part.name) ? assignedTo.at(part.name) : lookMaterial(object.name);
      draws.push_back({o, material, fmt::format("{} part '{}'", what, part.name), part.firstIndex, part.indexCount});
    }
  }
  // Each draw's material; each used material compiled once (programs below, by material).
  std::vector<SceneDocuments::Found> chosen(draws.size());
  for (size_t d = 0; d < draws.size(); ++d) {
    if (draws[d].material.empty()) {
      std::fprintf(stderr, "%s: error: %s: the look '%s' assigns it no material\n", source.c_str(), draws[d].what.c_str(),
                   scene.look.c_str());
      return kInvalidDocument;
    }
    auto found = documents.find(draws[d].material);
    if (auto* why = std::get_if<std::string>(&found)) {
      std::fprintf(stderr, "%s: error: %s: %s\n", source.c_str(), draws[d].what.c_str(), why->c_str());
      return kInvalidDocument;
    }
    chosen[d] = std::get<SceneDocuments::Found>(found);
  }

  OutputSet outputs;
  for (const std::string& output : options.outputs) {
    if (printError(outputs.declare(output, "-o"))) return kOutputFailed;
  }
  if (printError(outputs.checkDistinct())) return kUsage;
  for (MaterialPipeline* pipeline : documents.pipelines()) {
    if (printError(pipeline->checkOutputsAreNotInputs(outputs))) return kUsage;
  }
  if (!scene.file.empty() && printError(outputs.checkNotInput(scene.file, "the scene"))) return kUsage;
  for (const auto& [name, mesh] : meshes) {
    if (!mesh.file.empty() && printError(outputs.checkNotInput(mesh.file, "a mesh"))) return kUsage;
  }
  if (settings.environment == rt::Environment::Map && printError(outputs.checkNotInput(scene.environment.image, "the environment image"))) {
    return kUsage;
  }

  Device device(options.device);
  rt::AlbedoTables* tables = device.tables();
  if (!tables) return kNoDevice;
  // The image module loads while the shaders and pipelines compile, after the device (as in
  // runRender, cli/RenderCommand.cpp); the formats are checked before the first frame.
  rt::ImageModulePreload preload;
  std::unique_ptr<rt::EnvironmentMap> environment;
  const bool imageBehind = settings.environment == rt::Environment::Map && !scene.background;
  rt::RgbaImage behind;
  ImageFinish finish;
  finish.background = scene.background.value_or(glm::vec3(0.05f));
  finish.exposure = exposure;
  finish.tone = tone;
  finish.attributes = renderAttributes(options.file, settings.frames, exposure, tone);
  finish.format = options.format;

  std::string summary;
  int result = kOk;
  try {
    std::vector<MaterialToPrepare> toPrepare;
    std::set<const ir::Material*> seen;
    for (const SceneDocuments::Found& found : chosen) {
      if (seen.insert(found.material).second) toPrepare.push_back({found.pipeline, found.material});
    }
    auto prepared = prepareMaterials(toPrepare, session, *device.context(), glsl::ShaderKind::Raster, device.textures());
    if (!prepared) return kInvalidDocument;
    std::map<const ir::Material*, MaterialProgram> programs;
    for (size_t i = 0; i < toPrepare.size(); ++i) programs.emplace(toPrepare[i].material, std::move((*prepared)[i]));
    if (settings.environment == rt::Environment::Map) {
      std::vector<std::string> warnings;
      auto image = rt::EnvironmentMap::read(scene.environment.image, device.context()->maxImageDimension2D(), warnings);
      for (const std::string& w : warnings) std::fprintf(stderr, "warning: environment.file %s\n", w.c_str());
      if (auto* why = std::get_if<std::string>(&image)) {
        std::fprintf(stderr, "%s: error: environment.file: %s\n", source.c_str(), why->c_str());
        return kInvalidDocument;
      }
      environment = std::make_unique<rt::EnvironmentMap>(*device.context(), std::move(std::get<rt::RgbaImage>(image)));
      settings.environmentMap = environment.get();
    }
    if (imageBehind) behind = rt::renderBackground(settings);
    finish.behind = imageBehind ? &behind : nullptr;
    std::vector<rt::SceneObject> objects;
    for (size_t d = 0; d < draws.size(); ++d) {
      const MaterialProgram& program = programs.at(chosen[d].material);
      const SceneObjectSpec& object = scene.objects[draws[d].object];
      objects.push_back({&meshes.at(object.mesh).mesh, object.objectToWorld, program.resources.get(), &program.shader.interface,
                         &program.spirv, draws[d].firstIndex, draws[d].indexCount});
    }
    rt::Renderer renderer(*device.context(), *tables);
    Progress progress(settings.frames);
    rt::RenderResult image = renderer.renderScene(
        objects, settings,
        [&](uint32_t frame) { progress.step(fmt::format("{} objects, frame {}", scene.objects.size(), frame)); },
        [&] {
          if (int code = checkOutputFormats(options.outputs, options.format); code != kOk) throw OutputsRefused{code};
        });
    size_t bad = 0;
    for (float v : image.image.pixels) bad += std::isfinite(v) ? 0 : 1;
    for (const std::string& output : options.outputs) {
      if (printError(stageRender(output, image.image, finish, outputs))) return kOutputFailed;
    }
    if (bad > 0) {
      std::fprintf(stderr, "error: %zu pixel values are NaN or infinite (written for inspection)\n", bad);
      result = kInvalidDocument;
    }
    summary = fmt::format("{}: wrote {} ({}x{}, {} objects, {} materials, {} spp, {:.2f} ms per frame on {})",
                          scene.file.empty() ? scene.look : scene.file.filename().string(), fmt::join(options.outputs, ", "), settings.width, settings.height,
                          scene.objects.size(), programs.size(), settings.frames, image.msPerFrame, device.context()->deviceName());
  } catch (const OutputsRefused& refused) {
    return refused.code;
  } catch (const std::bad_alloc&) {
    throw;  // "out of memory", exit 4 (cli/Main.cpp)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kInvalidDocument;
  }
  if (!device.checkValidation()) return kInvalidDocument;
  if (printError(outputs.commit())) return kOutputFailed;
  if (!quiet() && !std::count(options.outputs.begin(), options.outputs.end(), "-")) std::printf("%s\n", summary.c_str());
  return result;
}

}  // namespace mxc::cli
