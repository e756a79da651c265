#include "cli/CompileCommand.h"

#include <chrono>
#include <cstdio>
#include <algorithm>
#include <memory>
#include <vector>

#include <fmt/format.h>

#include "cli/CompileBatch.h"
#include "cli/Depfile.h"
#include "cli/InterfaceOutputs.h"
#include "cli/OutputSet.h"
#include "cli/ExitCode.h"
#include "cli/MaterialPipeline.h"
#include "cli/Scene.h"
#include "cli/SceneDocuments.h"
#include "cli/Verbosity.h"
#include "compiler/document/Document.h"
#include "compiler/driver/ShaderGroups.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/glsl/ShaderInterface.h"
#include "compiler/target/Target.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::cli {

glsl::ShaderKind kindOf(const std::string& stage) {
  if (stage == "comp") return glsl::ShaderKind::Eval;
  if (stage == "furnace") return glsl::ShaderKind::Furnace;
  if (stage == "sample") return glsl::ShaderKind::Sample;
  return glsl::ShaderKind::Raster;
}

namespace {

/// One material to compile, in the pipeline of its document.
struct Unit {
  MaterialPipeline* pipeline;
  const ir::Material* material;
};

/// Compiles `units` to the options' outputs, all or nothing.
int compileUnits(const CompileOptions& options, Session& session, const std::vector<Unit>& units,
                 const std::vector<MaterialPipeline*>& pipelines, std::chrono::steady_clock::time_point start) {
  const bool several = units.size() > 1;
  if (printError(checkStandardOutput({options.output, options.glsl}, units.size()))) return kUsage;
  // Every output is declared and checked before anything is compiled or written.
  OutputSet outputs;
  const glsl::ShaderKind kind = kindOf(options.stage);
  const target::Target target = options.resolvedTarget;
  // Beside the shader file, its interface for a host renderer (and the vertex stage of a raster shader).
  const bool interfaces = !options.output.empty() && options.output != "-";
  for (const Unit& unit : units) {
    for (const auto& [path, option] : {std::pair{options.output, "-o"}, std::pair{options.glsl, "--glsl"}}) {
      if (path.empty()) continue;
      if (printError(outputs.declare(perMaterialPath(path, unit.material->name, several), option))) return kOutputFailed;
    }
    if (interfaces && printError(declareInterfaceOutputs(outputs, perMaterialPath(options.output, unit.material->name, several), kind))) {
      return kOutputFailed;
    }
  }
  std::filesystem::path tables;
  if (!options.tables.empty()) {
    std::string error;
    auto declared = declareTables(outputs, options.tables, error);
    if (!declared) {
      printError(error);
      return kOutputFailed;
    }
    tables = *declared;
    if (printError(stageTables(outputs, tables))) return kOutputFailed;
  }
  // What the command writes, for --list-outputs and as the depfile's targets.
  const std::vector<std::filesystem::path> written = outputs.paths();
  if (!options.depfile.empty()) {
    if (written.empty() || options.output.empty() || options.output == "-") {
      std::fprintf(stderr, "error: --depfile needs -o FILE: the depfile names the file it describes\n");
      return kUsage;
    }
    if (printError(outputs.declare(options.depfile, "--depfile"))) return kOutputFailed;
  }
  if (printError(outputs.checkDistinct())) return kUsage;
  for (MaterialPipeline* pipeline : pipelines) {
    if (printError(pipeline->checkOutputsAreNotInputs(outputs))) return kUsage;
  }
  if (options.listOutputs) {
    for (const std::filesystem::path& path : written) std::printf("%s\n", path.string().c_str());
    return kOk;
  }
  // A module on standard output would be mixed with the summary lines.
  const bool quiet = cli::quiet() || options.output == "-" || options.glsl == "-";
  int result = kOk;
  // The materials of one document compile by library, as a batch's do (driver/ShaderGroups.h):
  // the shaders of up to kGroupedShaders materials are built, their libraries planned as groups
  // (one glslang compile and one validation each), and the modules cut from them. A chunk at a
  // time, so that a document of many materials does not hold every shader's text at once.
  constexpr size_t kGroupedShaders = 16;
  const bool grouped = units.size() > 1 && std::all_of(units.begin(), units.end(), [&](const Unit& u) {
    return u.pipeline == units.front().pipeline;
  });
  std::vector<std::shared_ptr<const glsl::MaterialShader>> chunk;
  size_t chunkStart = 0;
  for (size_t u = 0; u < units.size(); ++u) {
    const Unit& unit = units[u];
    const ir::Material& material = *unit.material;
    Compiler& compiler = unit.pipeline->compiler();
    auto stage = std::chrono::steady_clock::now();
    if (grouped && (chunk.empty() || u >= chunkStart + chunk.size())) {
      chunk.clear();
      chunkStart = u;
      for (size_t k = u; k < std::min(units.size(), u + kGroupedShaders); ++k) {
        chunk.push_back(std::make_shared<const glsl::MaterialShader>(compiler.shader(*units[k].material)));
      }
      planShaderGroups(compiler.shaderCache(), chunk, compiler.request());
    }
    glsl::MaterialShader own;
    if (!grouped) own = compiler.shader(material);
    const glsl::MaterialShader& shader = grouped ? *chunk[u - chunkStart] : own;
    detail("{}: GLSL generated in {:.1f} ms", material.name, millisecondsSince(stage));
    stage = std::chrono::steady_clock::now();
    ShaderCache::Served served = ShaderCache::Served::Compiled;
    std::optional<std::vector<uint32_t>> words = compiler.spirv(shader, &served);
    if (served == ShaderCache::Served::SameCode) {
      detail("{}: SPIR-V of a shader with the same code, compiled for another material, taken in {:.1f} ms",
             material.name, millisecondsSince(stage));
    } else if (served == ShaderCache::Served::CutFromGroup) {
      detail("{}: SPIR-V cut from the compile of its library's group in {:.1f} ms", material.name, millisecondsSince(stage));
    } else {
      detail("{}: SPIR-V compiled{} and validated in {:.1f} ms", material.name, options.optimize ? ", optimised" : "",
             millisecondsSince(stage));
    }
    session.printDiagnostics();
    // Whether every target's devices take the shader's textures (its interface's descriptors:
    // the material's and mxc's own), whichever target this compile writes.
    if (auto warning = target::textureLimitWarning(
            target::resourcesOfInterface(glsl::shaderInterfaceJson(material, shader, kind, {})))) {
      std::fprintf(stderr, "warning: material %s: %s\n", material.name.c_str(), warning->c_str());
    }
    if (!options.glsl.empty()) {
      // The GLSL is produced even when glslang rejects it, so that the failing line can be read.
      const auto path = perMaterialPath(options.glsl, material.name, several);
      if (printError(outputs.stage(path, shader.glsl.text))) return kOutputFailed;
    }
    if (!words) {
      result = kInvalidDocument;
      continue;
    }
    size_t lines = 0;
    if (!options.output.empty()) {
      const auto path = perMaterialPath(options.output, material.name, several);
      std::string error;
      stage = std::chrono::steady_clock::now();
      const Staged staged = stageShaderOutputs(outputs, path, interfaces, compiler, material, shader, *words, kind,
                                               tables, unit.pipeline->documentFolder(), error, &lines);
      if (target != target::Target::Spirv) {
        detail("{}: {} written and checked in {:.1f} ms", material.name, target::targetName(target), millisecondsSince(stage));
      }
      session.printDiagnostics();
      if (staged == Staged::OutputFailed) {
        printError(error);
        return kOutputFailed;
      }
      if (staged == Staged::TranslationFailed) {
        result = kInvalidDocument;
        continue;
      }
    }
    if (!quiet) {
      std::vector<std::string> lobes;
      shader.interface.lobeKinds.forEach([&](ir::LobeKind k) { lobes.emplace_back(ir::lobeKindName(k)); });
      std::sort(lobes.begin(), lobes.end());
      const std::string language = target == target::Target::Spirv || lines == 0
                                      ? std::string()
                                      : fmt::format(", {} {} lines", target::targetName(target), lines);
      std::printf("%s: %s shader, %zu GLSL lines, %zu SPIR-V instructions%s; lobes %d (%s)%s%s\n", material.name.c_str(),
                  std::string(glsl::shaderKindName(kindOf(options.stage))).c_str(),
                  shader.glsl.origins.size(), spirv::instructionCount(*words), language.c_str(), shader.interface.lobes,
                  fmt::format("{}", fmt::join(lobes, ", ")).c_str(),
                  shader.interface.textures.empty() ? "" : fmt::format("; {} texture(s)", shader.interface.textures.size()).c_str(),
                  shader.interface.parameters.size() > 3
                      ? fmt::format("; {} parameter(s)", shader.interface.parameters.size() - 3).c_str()
                      : "");
    }
  }
  if (!options.depfile.empty()) {
    std::vector<std::filesystem::path> inputs;
    for (MaterialPipeline* pipeline : pipelines) {
      for (std::filesystem::path& path : pipeline->inputFiles()) inputs.push_back(std::move(path));
    }
    std::string error;
    const auto depfile = depfileText(written, inputs, error);
    if (!depfile) {
      std::fprintf(stderr, "error: --depfile %s: %s; nothing written\n", options.depfile.c_str(), error.c_str());
      return kOutputFailed;
    }
    if (printError(outputs.stage(options.depfile, *depfile))) return kOutputFailed;
  }
  // All or nothing: a SPIR-V module that was not produced leaves every output as it was.
  if (!outputs.complete()) {
    std::fprintf(stderr, "error: no output written: a shader did not compile\n");
  } else if (printError(outputs.commit())) {
    return kOutputFailed;
  }
  if (!quiet) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("compiled %zu material(s) in %.1f ms\n", units.size(), ms);
  }
  return result;
}


/// `mxc compile SCENE.json`: every material the scene's objects name or its look assigns, each
/// once, with its document's libraries and options.
int compileScene(const CompileOptions& options, std::chrono::steady_clock::time_point start) {
  if (!options.materials.material.empty()) {
    std::fprintf(stderr, "error: --material cannot be used with a scene file: the scene names its materials\n");
    return kUsage;
  }
  auto read = readScene(options.file);
  if (auto* why = std::get_if<std::string>(&read)) {
    std::fprintf(stderr, "%s\n", why->c_str());
    return kInvalidDocument;
  }
  const Scene& scene = std::get<Scene>(read);
  Session session;
  SceneDocuments documents(session);
  if (int code = documents.load(scene, options.materials, kindOf(options.stage), options.optimize, options.resolvedTarget);
      code != kOk) {
    return code;
  }
  auto used = documents.used(scene);
  if (auto* why = std::get_if<std::string>(&used)) {
    std::fprintf(stderr, "%s: error: %s\n", options.file.c_str(), why->c_str());
    return kInvalidDocument;
  }
  std::vector<Unit> units;
  for (const SceneDocuments::Found& hit : std::get<std::vector<SceneDocuments::Found>>(used)) {
    units.push_back({hit.pipeline, hit.material});
  }
  if (units.empty()) {
    std::fprintf(stderr, "%s: error: the scene uses no material (its objects name none and its look assigns none)\n",
                 options.file.c_str());
    return kInvalidDocument;
  }
  return compileUnits(options, session, units, documents.pipelines(), start);
}

}  // namespace

namespace {

/// Decides options.resolvedTarget; a message when --target and -o disagree.
std::optional<std::string> resolveTarget(CompileOptions& options, bool batch) {
  // -o's extension, when it names a language (a batch's -o is a folder).
  const std::string extension = std::filesystem::path(options.output).extension().string();
  // (A plain value and a flag, not an optional: GCC 12 warns of an optional enum read after a test.)
  target::Target named = target::Target::Spirv;
  bool extensionNames = false;
  if (!batch && options.output != "-") {
    if (auto t = target::targetOfExtension(extension)) named = *t, extensionNames = true;
  }
  if (options.target.empty()) {
    options.resolvedTarget = named;
    return std::nullopt;
  }
  auto chosen = target::parseTarget(options.target);
  if (!chosen) return fmt::format("--target {}: not one of {}", options.target, target::targetNames());
  if (extensionNames && named != *chosen) {
    return fmt::format("--target {} writes {} but -o {} names a {} file", options.target,
                       target::fileExtension(*chosen), options.output, target::targetName(named));
  }
  options.resolvedTarget = *chosen;
  return std::nullopt;
}

}  // namespace

int runCompile(const CompileOptions& given) {
  CompileOptions options = given;
  if (options.files.empty()) {
    // `mxc compile --tables DIR` alone: the tables, which depend on no document (a build
    // system's rule of their own).
    if (options.tables.empty()) {
      std::fprintf(stderr, "error: no document to compile (and no --tables DIR to write)\n");
      return kUsage;
    }
    OutputSet outputs;
    std::string error;
    auto tables = declareTables(outputs, options.tables, error);
    if (!tables) {
      printError(error);
      return kOutputFailed;
    }
    if (printError(stageTables(outputs, *tables)) || printError(outputs.commit())) return kOutputFailed;
    return kOk;
  }
  const bool batch = isBatch(options);
  if (auto why = resolveTarget(options, batch)) {
    std::fprintf(stderr, "error: %s\n", why->c_str());
    return kUsage;
  }
  if (batch) {
    if (!options.depfile.empty() || options.listOutputs) {
      std::fprintf(stderr, "error: --depfile and --list-outputs are for one document (a build rule per document)\n");
      return kUsage;
    }
    return runCompileBatch(options);
  }
  options.file = options.files.empty() ? std::string() : options.files.front();
  const auto start = std::chrono::steady_clock::now();
  if (isSceneFile(options.file)) return compileScene(options, start);
  Session session;
  MaterialPipeline pipeline(session);
  CompileRequest request;
  request.document = options.file;
  request.stage = kindOf(options.stage);
  request.optimize = options.optimize;
  request.target = options.resolvedTarget;
  // A library of definitions, or a document of only node graphs, is valid and has no shader:
  // said plainly, and not a failure (a batch over MaterialX's test suite meets many).
  if (int code = pipeline.run(std::move(request), options.materials, false); code != kOk) return code;
  if (pipeline.materials().empty()) {
    if (!quiet()) std::printf("nothing to compile: %s has no material and no surface shader\n", options.file.c_str());
    return kOk;
  }
  std::vector<Unit> units;
  for (const ir::Material& material : pipeline.materials()) units.push_back({&pipeline, &material});
  return compileUnits(options, session, units, {&pipeline}, start);
}

}  // namespace mxc::cli
