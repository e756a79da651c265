#include "cli/SpecializationBench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <sstream>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "cli/ExitCode.h"
#include "cli/MaterialXShader.h"
#include "cli/OutputSet.h"
#include "cli/SpecializationReport.h"
#include "compiler/common/EmbeddedFile.h"
#include "compiler/driver/Compiler.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "runtime/ImageDifference.h"
#include "runtime/MaterialResources.h"
#include "runtime/Renderer.h"

namespace mxc {
std::span<const EmbeddedFile> comparisonDocumentFiles();  // cmake/EmbedFiles.cmake: cli/comparison-documents.txt
}  // namespace mxc

namespace mxc::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void log(const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }

/// The fixed set: the documents of the side-by-side comparison with MaterialX
/// (cli/comparison-documents.txt, which tests/bench/materialx_compare.py reads too), and two plain
/// diffuse presets for the diffuse target.
std::vector<fs::path> fixedSet(const fs::path& corpus) {
  std::vector<fs::path> files;
  for (const EmbeddedFile& list : comparisonDocumentFiles()) {
    std::istringstream lines{std::string(list.contents)};
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (!line.empty() && line[0] != '#') files.push_back(corpus / line);
    }
  }
  for (const char* name : kDiffuseMaterials) files.push_back(corpus / "openpbr-presets" / name);
  return files;
}

struct Scene {
  std::string name;
  std::string definition;  // for the report
  rt::RenderSettings settings;
};

/// The first is the comparison harness's (one directional light of irradiance 3, no
/// environment: what MaterialX's shaders were generated for); the second `mxc render`'s default.
std::vector<Scene> benchScenes(uint32_t size, uint32_t frames) {
  const glm::vec3 key = glm::normalize(glm::vec3(-1.0f, 1.2f, 1.5f));
  std::vector<Scene> scenes(2);
  scenes[0].name = "key light";
  scenes[0].definition = "one directional light towards (-1, 1.2, 1.5), irradiance 3, no environment";
  scenes[0].settings.environment = rt::Environment::None;
  scenes[0].settings.lights.push_back({rt::Light::Kind::Directional, key, glm::vec3(1.0f), 3.0f});
  scenes[1].name = "sky + key light";
  scenes[1].definition = "the analytic sky (mxc render's default) and that light at irradiance 2";
  scenes[1].settings.environment = rt::Environment::Sky;
  scenes[1].settings.lights.push_back({rt::Light::Kind::Directional, key, glm::vec3(1.0f), 2.0f});
  for (Scene& s : scenes) {
    s.settings.width = s.settings.height = size;
    s.settings.frames = frames;
  }
  return scenes;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// One document's MaterialX shaders, from the comparison harness's manifest.
struct MaterialXEntry {
  fs::path mtlx;
  std::string material;  ///< empty: the document's only one
  fs::path vertex, pixel, uniforms;
};

/// The manifest's entries; an error message naming the file instead.
std::variant<std::vector<MaterialXEntry>, std::string> readManifest(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    return fmt::format("{}: not a file (write it with python3 tests/bench/materialx_compare.py --specialization)",
                       path.string());
  }
  try {
    const nlohmann::json manifest = nlohmann::json::parse(readText(path));
    std::vector<MaterialXEntry> out;
    for (const nlohmann::json& e : manifest.at("materials")) {
      out.push_back({e.at("mtlx").get<std::string>(), e.value("material", ""), e.at("vertex").get<std::string>(),
                     e.at("pixel").get<std::string>(), e.at("uniforms").get<std::string>()});
    }
    return out;
  } catch (const std::exception& e) {
    return fmt::format("{}: not a manifest of tests/bench/materialx_compare.py: {}", path.string(), e.what());
  }
}

/// The entry for a document's material, or null.
const MaterialXEntry* findEntry(const std::vector<MaterialXEntry>& entries, const fs::path& file,
                                const std::string& material) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  for (const MaterialXEntry& e : entries) {
    std::error_code ec2;
    if (fs::weakly_canonical(e.mtlx, ec2) == canonical && (e.material.empty() || e.material == material)) return &e;
  }
  return nullptr;
}

/// One of a material's two shaders, compiled and ready to render.
struct CompiledShader {
  std::unique_ptr<Workspace> workspace;  ///< the shader's locations point into its sources
  glsl::MaterialShader shader;
  std::vector<uint32_t> words;
  std::unique_ptr<rt::MaterialResources> resources;
  ShaderFigures figures;
  std::string model;
};

/// The median of `repeat` compilations from the document to validated SPIR-V, each in a fresh
/// workspace (a second load of one path would come from the loader's cache), then the -O
/// counts per scene. Nullopt with the diagnostics printed when it does not compile.
std::optional<CompiledShader> compileShader(const lib::LibraryStack& libraries, const fs::path& file,
                                            const std::string& material, bool specialize, int repeat,
                                            const std::vector<Scene>& scenes, rt::VulkanContext& context,
                                            rt::TextureCache* textures) {
  CompiledShader out;
  std::vector<double> times;
  fs::path folder;
  for (int r = 0; r < repeat; ++r) {
    out.workspace = std::make_unique<Workspace>();
    const auto start = Clock::now();
    CompileRequest request;
    request.document = file;
    request.libraries = &libraries;
    request.material = material;
    request.specialize = specialize;
    Compiler compiler(*out.workspace, request);
    std::vector<ir::Material>& materials = compiler.materials();
    if (out.workspace->diagnostics.hasErrors() || materials.empty()) {
      std::fprintf(stderr, "%s", out.workspace->diagnostics.format().c_str());
      return std::nullopt;
    }
    out.shader = compiler.shader(materials.front(), glsl::ShaderKind::Raster);
    auto words = spirv::compile(out.shader.glsl, {}, out.workspace->diagnostics);
    times.push_back(msSince(start));
    if (!words) {
      std::fprintf(stderr, "%s", out.workspace->diagnostics.format().c_str());
      return std::nullopt;
    }
    out.words = std::move(*words);
    out.model = materials.front().shader;
    folder = compiler.documentFolder();
  }
  out.figures.toSpirvMs = medianOf(times);
  out.figures.instructions = spirv::instructionCount(out.words);
  for (const Scene& scene : scenes) {
    // The general shader's pipeline gets no constants (it keeps their defaults, which read the
    // view): one -O module serves every scene.
    if (!specialize && !out.figures.optimized.empty()) {
      out.figures.optimized.push_back(out.figures.optimized.front());
      continue;
    }
    spirv::CompileOptions options;
    options.optimize = true;
    if (specialize) options.specialization = rt::sceneSpecialization(scene.settings);
    auto optimized = spirv::compile(out.shader.glsl, options, out.workspace->diagnostics);
    if (!optimized) {
      std::fprintf(stderr, "%s", out.workspace->diagnostics.format().c_str());
      return std::nullopt;
    }
    out.figures.optimized.push_back(spirv::instructionCount(*optimized));
  }
  Diagnostics diagnostics;
  out.resources = std::make_unique<rt::MaterialResources>(context, out.shader.interface, folder, diagnostics, textures);
  for (const Diagnostic& d : diagnostics.all()) std::fprintf(stderr, "%s\n", d.format().c_str());
  if (diagnostics.hasErrors()) return std::nullopt;
  return out;
}

/// What the measurement of the materials needs from the run.
struct BenchRun {
  const SpecializationBenchOptions& options;
  rt::VulkanContext& context;
  rt::TextureCache* textures;
  rt::Renderer& renderer;
  const rt::Mesh& sphere;
  const lib::LibraryStack& libraries;
  std::vector<Scene> scenes;
  std::vector<MaterialXEntry> materialx;
};

/// MaterialX's shader of one document: its pixel stage's size and glslang time, and a render of
/// the first scene. Nullopt (with the reason printed) when its GLSL does not compile or run.
std::optional<VariantFigures> measureMaterialX(BenchRun& run, const MaterialXEntry& entry) {
  const std::string vertex = readText(entry.vertex), pixel = readText(entry.pixel);
  const spirv::GlslSource source{pixel, spirv::Stage::Fragment, "MaterialX pixel stage", {}};
  VariantFigures out;
  std::vector<double> times;
  for (int r = 0; r < run.options.repeat; ++r) {
    Diagnostics diagnostics;
    const auto start = Clock::now();
    auto words = spirv::compile(source, {}, diagnostics);
    times.push_back(msSince(start));
    if (!words) {
      log(fmt::format("warning: {}: MaterialX's pixel stage does not compile: {}", entry.pixel.string(),
                      diagnostics.format()));
      return std::nullopt;
    }
    out.shader.instructions = spirv::instructionCount(*words);
  }
  out.shader.toSpirvMs = medianOf(times);
  Diagnostics diagnostics;
  spirv::CompileOptions optimize;
  optimize.optimize = true;
  if (auto optimized = spirv::compile(source, optimize, diagnostics)) {
    out.shader.optimized.push_back(spirv::instructionCount(*optimized));
  }
  try {
    auto loaded = MaterialXShader::load(vertex, pixel, parseMaterialXUniforms(readText(entry.uniforms)),
                                        entry.mtlx.parent_path());
    if (auto* error = std::get_if<std::string>(&loaded)) {
      log(fmt::format("warning: {}: {}", entry.pixel.string(), *error));
      return std::nullopt;
    }
    std::vector<std::string> warnings;
    rt::RenderResult r = std::get<MaterialXShader>(loaded).render(run.context, run.renderer, run.sphere,
                                                                  run.scenes[0].settings, warnings);
    for (const std::string& w : warnings) log(fmt::format("warning: {}: {}", entry.pixel.string(), w));
    out.scenes.push_back({r.msPerFrame, r.pipelineMs});
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    log(fmt::format("warning: {}: {}", entry.uniforms.string(), e.what()));
    return std::nullopt;
  }
  return out;
}

/// Both shaders of one material in every scene, and MaterialX's when the manifest has it.
std::optional<SpecializationRow> measureMaterial(BenchRun& run, const fs::path& file, const std::string& material) {
  SpecializationRow row;
  row.name = material;
  row.source = file.filename().string();
  const SpecializationBenchOptions& o = run.options;
  auto general = compileShader(run.libraries, file, material, false, o.repeat, run.scenes, run.context, run.textures);
  auto specialized = compileShader(run.libraries, file, material, true, o.repeat, run.scenes, run.context, run.textures);
  if (!general || !specialized) return std::nullopt;
  row.model = specialized->model;
  row.general.shader = general->figures;
  row.specialized.shader = specialized->figures;
  for (const Scene& scene : run.scenes) {
    rt::RgbaImage images[2];
    int k = 0;
    for (auto [compiled, figures, specialize] : {std::tuple{&*general, &row.general, false},
                                                 std::tuple{&*specialized, &row.specialized, true}}) {
      rt::RenderSettings s = scene.settings;
      s.specialize = specialize;
      rt::RenderResult r =
          run.renderer.render(run.sphere, *compiled->resources, compiled->shader.interface, compiled->words, s);
      figures->scenes.push_back({r.msPerFrame, r.pipelineMs});
      images[k++] = std::move(r.image);
    }
    row.imageDifference.push_back(rt::compareImages(images[1], images[0]).mean);
  }
  if (const MaterialXEntry* entry = findEntry(run.materialx, file, material)) row.materialx = measureMaterialX(run, *entry);
  return row;
}

std::string reproduce(const SpecializationBenchOptions& o) {
  const SpecializationBenchOptions d;
  std::string c = "mxc bench specialize";
  if (o.size != d.size) c += fmt::format(" --size {}", o.size);
  if (o.frames != d.frames) c += fmt::format(" --frames {}", o.frames);
  if (o.repeat != d.repeat) c += fmt::format(" --repeat {}", o.repeat);
  if (!o.materialx.empty()) c += " --materialx " + o.materialx;
  if (o.reportDir != d.reportDir) c += " --report-dir " + o.reportDir;
  for (const std::string& f : o.files) c += " " + f;
  return c;
}

}  // namespace

int runSpecializationBench(const SpecializationBenchOptions& options) {
  std::vector<fs::path> files;
  if (options.files.empty()) {
    const fs::path corpus = options.corpus.empty() ? fs::path(MXC_CORPUS_DIR) : fs::path(options.corpus);
    files = fixedSet(corpus);
    for (const fs::path& f : files) {
      std::error_code ec;
      if (!fs::is_regular_file(f, ec)) {
        std::fprintf(stderr, "error: the fixed set's document '%s' is missing: pass --corpus DIR (the folder with "
                     "openpbr-presets/ and materialx/examples/) or documents\n", f.string().c_str());
        return kUsage;
      }
    }
  } else {
    for (const std::string& f : options.files) files.emplace_back(f);
  }
  std::vector<MaterialXEntry> materialx;
  if (!options.materialx.empty()) {
    auto manifest = readManifest(options.materialx);
    if (auto* error = std::get_if<std::string>(&manifest)) {
      std::fprintf(stderr, "error: --materialx %s\n", error->c_str());
      return kInvalidDocument;
    }
    materialx = std::move(std::get<0>(manifest));
  }

  // The library, loaded once: its load is not part of a shader's compile time.
  Workspace library;
  if (!library.loadLibraries(!options.libraries.noBuiltin, options.libraries.folders)) {
    std::fprintf(stderr, "%s", library.diagnostics.format().c_str());
    return kInvalidDocument;
  }
  // The materials of each document, and the outputs, refused before minutes of measurement.
  std::vector<std::pair<fs::path, std::string>> materials;
  for (const fs::path& f : files) {
    Workspace workspace;
    CompileRequest request;
    request.document = f;
    request.libraries = &library.libraries;
    Compiler compiler(workspace, request);
    const std::vector<std::string>& names = compiler.materialNames();
    if (workspace.diagnostics.hasErrors()) {
      std::fprintf(stderr, "%s", workspace.diagnostics.format().c_str());
      return kInvalidDocument;
    }
    for (const std::string& name : names) materials.emplace_back(f, name);
  }
  if (printError(rt::loadImageModule())) return kOutputFailed;
  const fs::path dir = options.reportDir;
  const fs::path md = dir / "specialization.md", csv = dir / "specialization.csv";
  OutputSet outputs;
  for (const fs::path& p : {md, csv}) {
    if (printError(outputs.declare(p, "--report-dir"))) return kOutputFailed;
  }
  for (const fs::path& f : files) {
    if (printError(outputs.checkNotInput(f, "a document"))) return kUsage;
  }

  Device device(options.device);
  rt::AlbedoTables* tables = device.tables();
  rt::TextureCache* textures = device.textures();
  if (!tables || !textures) return kNoDevice;
  SpecializationReport report;
  report.device = device.context()->deviceName();
  report.command = reproduce(options);
  report.materialxManifest = options.materialx;
  {
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
    report.date = date;
  }
  report.size = uint32_t(options.size);
  report.frames = uint32_t(options.frames);
  report.repeat = options.repeat;
  try {
    rt::Renderer renderer(*device.context(), *tables);
    const rt::Mesh sphere = rt::makeSphere();
    BenchRun run{options,  *device.context(), textures, renderer, sphere, library.libraries,
                 benchScenes(report.size, report.frames), std::move(materialx)};
    for (const Scene& s : run.scenes) report.scenes.push_back({s.name, s.definition});
    for (size_t i = 0; i < materials.size(); ++i) {
      log(fmt::format("[{}/{}] {} ({})", i + 1, materials.size(), materials[i].second,
                      materials[i].first.filename().string()));
      auto row = measureMaterial(run, materials[i].first, materials[i].second);
      if (!row) return kInvalidDocument;
      report.materials.push_back(std::move(*row));
    }
  } catch (const std::bad_alloc&) {
    throw;  // "out of memory", exit 4 (cli/Main.cpp)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kInvalidDocument;
  }
  if (!device.checkValidation()) return kInvalidDocument;

  std::optional<std::string> error = outputs.stage(md, specializationMarkdown(report));
  if (!error) error = outputs.stage(csv, specializationCsv(report));
  if (!error) error = outputs.commit();
  if (printError(error)) return kOutputFailed;
  std::printf("wrote %s and %s (%zu materials on %s)\n", md.string().c_str(), csv.string().c_str(),
              report.materials.size(), report.device.c_str());
  std::printf("median specialized / general: instructions %.3f, frame time (%s) %.3f\n", medianInstructionRatio(report),
              report.scenes.at(0).name.c_str(), medianFrameRatio(report, 0));
  return kOk;
}

}  // namespace mxc::cli
