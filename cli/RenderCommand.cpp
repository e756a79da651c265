#include "cli/Verbosity.h"
#include "cli/RenderCommand.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "compiler/common/Parallel.h"

#include "cli/ExitCode.h"
#include "cli/Harness.h"
#include "cli/MaterialPipeline.h"
#include "cli/MeshArgument.h"
#include "cli/OutputSet.h"
#include "cli/RenderOutput.h"
#include "cli/Scene.h"
#include "cli/SearchPaths.h"
#include "compiler/glsl/Contract.h"
#include "runtime/EnvironmentMap.h"
#include "runtime/ImageIO.h"
#include "runtime/Renderer.h"

namespace mxc::cli {

namespace {

/// "a,b,c" to numbers; false when it is not `count` finite numbers.
bool parseNumbers(const std::string& text, size_t count, std::vector<float>& out) {
  out.clear();
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ',')) {
    try {
      size_t used = 0;
      float v = std::stof(part, &used);
      if (!std::isfinite(v) || part.find_first_not_of(" \t", used) != std::string::npos) return false;
      out.push_back(v);
    } catch (const std::exception&) {
      return false;
    }
  }
  return out.size() == count;
}

/// KIND:X,Y,Z[:INTENSITY[:R,G,B]], KIND dir or point.
bool parseLight(const std::string& text, rt::Light& light, std::string& why) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ':')) parts.push_back(part);
  if (parts.size() < 2 || parts.size() > 4 || (parts[0] != "dir" && parts[0] != "point")) {
    why = "expected dir:X,Y,Z[:INTENSITY[:R,G,B]] or point:X,Y,Z[:INTENSITY[:R,G,B]]";
    return false;
  }
  light.kind = parts[0] == "dir" ? rt::Light::Kind::Directional : rt::Light::Kind::Point;
  std::vector<float> v;
  if (!parseNumbers(parts[1], 3, v)) {
    why = "the position or direction must be three numbers X,Y,Z";
    return false;
  }
  light.vector = {v[0], v[1], v[2]};
  if (light.kind == rt::Light::Kind::Directional) {
    if (glm::dot(light.vector, light.vector) < 1e-12f) {
      why = "a directional light needs a non-zero direction";
      return false;
    }
    light.vector = glm::normalize(light.vector);
  }
  if (parts.size() > 2) {
    if (!parseNumbers(parts[2], 1, v) || v[0] < 0.0f) {
      why = "the intensity must be a number >= 0";
      return false;
    }
    light.intensity = v[0];
  }
  if (parts.size() > 3) {
    if (!parseNumbers(parts[3], 3, v) || v[0] < 0.0f || v[1] < 0.0f || v[2] < 0.0f) {
      why = "the colour must be three numbers >= 0";
      return false;
    }
    light.color = {v[0], v[1], v[2]};
  }
  return true;
}

/// The camera of the options: framed to the mesh unless a position is given.
std::optional<std::string> chooseCamera(const RenderOptions& options, const MeshChoice& mesh, rt::RenderSettings& settings) {
  const rt::MeshBounds bounds = rt::meshBounds(mesh.mesh);
  std::vector<float> v;
  auto vector = [&](const std::string& text, const char* option, glm::vec3& out) -> std::optional<std::string> {
    if (!parseNumbers(text, 3, v)) return fmt::format("{} {}: expected X,Y,Z", option, text);
    out = {v[0], v[1], v[2]};
    return std::nullopt;
  };
  rt::Camera& camera = settings.camera;
  if (options.cameraPosition.empty()) {
    if (!options.cameraTarget.empty()) return std::string("--camera-target needs --camera-position");
    camera = rt::frameBounds(bounds, mesh.viewDirection, options.fovDegrees, float(settings.width) / float(settings.height));
  } else {
    camera.fovDegrees = options.fovDegrees;
    if (auto why = vector(options.cameraPosition, "--camera-position", camera.eye)) return why;
    camera.target = bounds.center;
    if (!options.cameraTarget.empty()) {
      if (auto why = vector(options.cameraTarget, "--camera-target", camera.target)) return why;
    }
    rt::fitClipPlanes(camera, bounds);
  }
  if (!options.cameraUp.empty()) {
    if (auto why = vector(options.cameraUp, "--camera-up", camera.up)) return why;
  }
  if (auto why = rt::scaleProblem(bounds, camera)) return why;
  if (auto why = rt::cameraProblem(camera)) return fmt::format("the camera: {}", *why);
  return std::nullopt;
}

}  // namespace

bool parseRenderSize(const std::string& text, uint32_t& width, uint32_t& height) {
  const size_t x = text.find('x');
  auto one = [](const std::string& part, uint32_t& out) {
    if (part.empty() || part.size() > 5 || part.find_first_not_of("0123456789") != std::string::npos) return false;
    const unsigned long v = std::stoul(part);  // 1 to 5 digits: no overflow
    if (v < 8 || v > 8192) return false;
    out = static_cast<uint32_t>(v);
    return true;
  };
  if (x == std::string::npos) return one(text, width) && one(text, height);
  return one(text.substr(0, x), width) && one(text.substr(x + 1), height);
}

int runRender(const RenderOptions& options) {
  if (printError(checkFormatOption(options.outputs, options.format))) return kUsage;
  if (isSceneFile(options.file)) return runSceneRender(options);
  rt::RenderSettings settings;
  if (!parseRenderSize(options.size, settings.width, settings.height)) {
    std::fprintf(stderr, "error: --size %s: expected N or WxH, each from 8 to 8192\n", options.size.c_str());
    return kUsage;
  }
  settings.frames = static_cast<uint32_t>(options.spp);
  settings.specialize = !options.materials.noSpecialize;
  const bool environmentImage = options.environment != "none" && options.environment != "white" &&
                                options.environment != "sky";
  settings.environment = options.environment == "none"    ? rt::Environment::None
                         : options.environment == "white" ? rt::Environment::White
                         : options.environment == "sky"   ? rt::Environment::Sky
                                                          : rt::Environment::Map;
  settings.environmentIntensity = options.environmentIntensity;
  settings.environmentRotation = options.environmentRotation;
  settings.emissionScale = options.emissionScale;
  if (options.lights.empty() && !environmentImage) {
    // The default key light: from the upper left, in front. An environment image is its own
    // lighting, as in a look-development viewer.
    settings.lights.push_back({rt::Light::Kind::Directional, glm::normalize(glm::vec3(-1.0f, 1.2f, 1.5f)), glm::vec3(1.0f), 2.0f});
  }
  for (const std::string& text : options.lights) {
    if (text == "none") continue;
    rt::Light light;
    std::string why;
    if (!parseLight(text, light, why)) {
      std::fprintf(stderr, "error: --light %s: %s\n", text.c_str(), why.c_str());
      return kUsage;
    }
    settings.lights.push_back(light);
  }
  if (settings.lights.size() > glsl::kMaxLights) {
    std::fprintf(stderr, "error: at most %u lights\n", glsl::kMaxLights);
    return kUsage;
  }
  // The background: a constant colour under 8-bit outputs, or the environment image behind the
  // mesh under every output (it is radiance, like the render).
  std::vector<float> background;
  const bool imageBackground = environmentImage && options.background.empty();
  const std::string backgroundText = options.background.empty() ? kDefaultBackground : options.background;
  if (!parseNumbers(backgroundText, 3, background)) {
    std::fprintf(stderr, "error: --background %s: expected R,G,B\n", backgroundText.c_str());
    return kUsage;
  }
  auto chosen = chooseMesh(options.mesh, searchPaths(options.materials.searchPaths));
  if (auto* why = std::get_if<std::string>(&chosen)) {
    std::fprintf(stderr, "error: --mesh %s\n", why->c_str());
    return kInvalidDocument;
  }
  const MeshChoice& mesh = std::get<MeshChoice>(chosen);
  if (auto why = chooseCamera(options, mesh, settings)) {
    std::fprintf(stderr, "error: %s\n", why->c_str());
    return kUsage;
  }
  if (!options.look.empty()) {
    // One image of the look's assignments: a scene of one object, the mesh, named after it.
    if (!options.materials.material.empty()) {
      std::fprintf(stderr, "error: --material and --look: the look chooses the materials\n");
      return kUsage;
    }
    Scene scene;
    scene.documents = {options.file};
    scene.look = options.look;
    SceneObjectSpec object;
    object.name = std::filesystem::path(options.mesh).stem().string();
    object.mesh = options.mesh;
    scene.objects = {object};
    scene.lights = settings.lights;
    scene.environment = {settings.environment, environmentImage ? options.environment : std::string(),
                         settings.environmentIntensity, settings.environmentRotation};
    scene.camera = settings.camera;
    scene.width = settings.width;
    scene.height = settings.height;
    scene.spp = settings.frames;
    scene.exposure = options.exposure;
    scene.toneMapping = options.toneMapping;
    if (!options.background.empty()) scene.background = glm::vec3(background[0], background[1], background[2]);
    std::map<std::string, MeshChoice> meshes;
    meshes.emplace(options.mesh, std::get<MeshChoice>(std::move(chosen)));
    return renderSceneData(scene, options, std::move(meshes));
  }

  Session session;
  MaterialPipeline pipeline(session);
  CompileRequest request;
  request.document = options.file;
  if (int code = pipeline.run(std::move(request), options.materials); code != kOk) return code;
  const bool several = pipeline.materials().size() > 1;
  if (printError(checkStandardOutput(options.outputs, pipeline.materials().size()))) return kUsage;
  OutputSet outputs;
  for (const ir::Material& material : pipeline.materials()) {
    for (const std::string& output : options.outputs) {
      if (printError(outputs.declare(perMaterialPath(output, material.name, several), "-o"))) return kOutputFailed;
    }
  }
  if (printError(outputs.checkDistinct()) || printError(pipeline.checkOutputsAreNotInputs(outputs))) return kUsage;
  if (!mesh.file.empty() && printError(outputs.checkNotInput(mesh.file, "the mesh"))) {
    return kUsage;
  }
  if (environmentImage && printError(outputs.checkNotInput(options.environment, "the environment image"))) {
    return kUsage;
  }
  Device device(options.device);
  rt::AlbedoTables* tables = device.tables();
  if (!tables) return kNoDevice;
  // The image module (OpenImageIO, 0.2-0.4 s to load) loads while the shaders and pipelines
  // compile. It starts after the device: the dynamic loader loads one library at a time, and the
  // Vulkan driver would wait behind the module's 260. The environment image, which needs the
  // module, is read after the shaders; the outputs are checked before the first frame.
  rt::ImageModulePreload preload;
  std::unique_ptr<rt::EnvironmentMap> environment;
  const rt::ToneMapping toneMapping = rt::parseToneMapping(options.toneMapping).value_or(rt::ToneMapping::AcesFit);
  // What a reader of the file needs to know how its values were made.
  rt::RgbaImage behind;
  ImageFinish finish;
  finish.background = glm::vec3(background[0], background[1], background[2]);
  finish.exposure = options.exposure;
  finish.tone = toneMapping;
  finish.attributes = renderAttributes(options.file, settings.frames, options.exposure, toneMapping);
  finish.format = options.format;
  int result = kOk;
  std::vector<std::string> wrote;
  try {
    // Every material is compiled (and its textures read) before the first frame: a material
    // that fails stops the command before minutes of rendering, not after.
    std::vector<MaterialToPrepare> toPrepare;
    for (const ir::Material& material : pipeline.materials()) toPrepare.push_back({&pipeline, &material});
    auto prepared = prepareMaterials(toPrepare, session, *device.context(), glsl::ShaderKind::Raster, device.textures());
    if (!prepared) return kInvalidDocument;
    const std::vector<MaterialProgram>& programs = *prepared;
    if (environmentImage) {
      std::vector<std::string> warnings;
      auto read = rt::EnvironmentMap::read(options.environment, device.context()->maxImageDimension2D(), warnings);
      for (const std::string& w : warnings) std::fprintf(stderr, "warning: --env %s\n", w.c_str());
      if (auto* why = std::get_if<std::string>(&read)) {
        std::fprintf(stderr, "error: --env %s\n", why->c_str());
        return kInvalidDocument;
      }
      environment = std::make_unique<rt::EnvironmentMap>(*device.context(), std::move(std::get<rt::RgbaImage>(read)));
      settings.environmentMap = environment.get();
    }
    if (imageBackground) behind = rt::renderBackground(settings);
    finish.behind = imageBackground ? &behind : nullptr;
    auto checkOutputs = [&] {
      if (int code = checkOutputFormats(options.outputs, options.format); code != kOk) throw OutputsRefused{code};
    };
    rt::Renderer renderer(*device.context(), *tables);
    // One bar over every frame of every material: its estimate covers the whole command.
    Progress progress(size_t{settings.frames} * programs.size());
    // Each material alone in its own image; every material's pipelines compile together first.
    std::vector<rt::SceneObject> objects;
    for (const MaterialProgram& program : programs) {
      objects.push_back({&mesh.mesh, settings.objectToWorld, program.resources.get(), &program.shader.interface,
                         &program.spirv});
    }
    // Each image is staged as soon as it is done (one held at a time); an output that cannot be
    // staged stops the render.
    auto finished = [&](size_t m, rt::RenderResult&& image) {
      const ir::Material& material = pipeline.materials()[m];
      size_t bad = 0;
      for (float v : image.image.pixels) bad += std::isfinite(v) ? 0 : 1;
      std::vector<std::string> written;
      for (const std::string& output : options.outputs) {
        const auto path = perMaterialPath(output, material.name, several);
        if (printError(stageRender(path, image.image, finish, outputs))) throw OutputsRefused{kOutputFailed};
        written.push_back(path.string());
      }
      if (bad > 0) {
        std::fprintf(stderr, "error: %s: %zu pixel values are NaN or infinite (written for inspection)\n",
                     material.name.c_str(), bad);
        result = kInvalidDocument;
      }
      wrote.push_back(fmt::format("{}: wrote {} ({}x{}, {} spp, {:.2f} ms per frame on {})", material.name,
                                  fmt::join(written, ", "), settings.width, settings.height, settings.frames,
                                  image.msPerFrame, device.context()->deviceName()));
    };
    // A few materials' pipelines at a time: enough to keep every core compiling, few enough that
    // a document of hundreds of materials does not hold hundreds of pipelines (tens of MB each).
    const size_t batch = 2 * coreCount();
    for (size_t first = 0; first < objects.size(); first += batch) {
      const std::vector<rt::SceneObject> part(objects.begin() + std::ptrdiff_t(first),
                                              objects.begin() + std::ptrdiff_t(std::min(first + batch, objects.size())));
      renderer.renderEach(
          part, settings, [&](size_t k, rt::RenderResult&& image) { finished(first + k, std::move(image)); },
          [&](size_t k, uint32_t frame) {
            const std::string& name = pipeline.materials()[first + k].name;
            progress.step(several ? fmt::format("{} ({}/{}) frame {}", name, first + k + 1, programs.size(), frame)
                                  : fmt::format("{} frame {}", name, frame));
          },
          checkOutputs);
    }
  } catch (const OutputsRefused& refused) {
    return refused.code;
  } catch (const std::bad_alloc&) {
    throw;  // "out of memory", exit 4 (cli/Main.cpp)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kInvalidDocument;
  }
  if (!device.checkValidation()) return kInvalidDocument;
  // Every image of every material, together (cli/OutputSet.h).
  if (printError(outputs.commit())) return kOutputFailed;
  // An image on standard output would be mixed with the summary lines.
  if (!quiet() && !std::count(options.outputs.begin(), options.outputs.end(), "-")) {
    for (const std::string& line : wrote) std::printf("%s\n", line.c_str());
  }
  return result;
}

}  // namespace mxc::cli
