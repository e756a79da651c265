// The C++ half of the side-by-side comparison with MaterialX (tests/bench/materialx_compare.py
// runs it). For each material of a manifest written by the script, with MaterialX's Vulkan GLSL
// already generated and timed there:
//   - times mxc from the .mtlx file to GLSL (parse, resolve, lower, passes, GLSL) and from GLSL
//     to a validated SPIR-V module, with mxc's library loaded once beforehand (reported apart,
//     as the script reports MaterialX's library load apart);
//   - compiles both sides' GLSL with the same glslang and SPIRV-Tools (MaterialX's vertex and
//     pixel stages; mxc's raster fragment shader) and counts SPIR-V instructions before and
//     after SPIRV-Tools' performance passes;
//   - renders both on the same sphere, camera and directional light in mxc's raster harness
//     (MaterialX's shader through MaterialXShader: its uniform blocks found by reflection),
//     environment lighting off on both sides; reports ms per frame and the image difference
//     over the pixels both cover, and writes both images (PNG) for a person to look at.
// Writes the figures as JSON for the script's report.
//
//   build/tests/bench/compare_bench MANIFEST.json RESULTS.json [--repeat N] [--size N]
//                                   [--frames N] [--images DIR]
//
// MANIFEST: {"materials": [{"name", "mtlx", "material", "vertex", "pixel", "uniforms"}]}
// (paths to files; uniforms: MaterialX's uniform blocks and values, as the script wrote them).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compiler/common/LargeStack.h"
#include "compiler/driver/Compiler.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "runtime/AlbedoTables.h"
#include "runtime/ImageIO.h"
#include "runtime/MaterialResources.h"
#include "runtime/Renderer.h"
#include "cli/MaterialXShader.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Instruction counts of one GLSL stage, plain and optimised, and the glslang + validation time.
struct ModuleFigures {
  std::vector<uint32_t> words;  ///< the plain module (empty on failure)
  size_t instructions = 0;
  size_t optimized = 0;
  double compileMs = 0.0;
  std::string error;
};

ModuleFigures compileStage(mxc::spirv::GlslSource source, int repeat) {
  ModuleFigures out;
  std::vector<double> times;
  for (int r = 0; r < repeat; ++r) {
    mxc::Diagnostics diagnostics;
    const auto start = Clock::now();
    auto words = mxc::spirv::compile(source, {}, diagnostics);
    times.push_back(msSince(start));
    if (!words) {
      out.error = diagnostics.format();
      return out;
    }
    out.instructions = mxc::spirv::instructionCount(*words);
    out.words = std::move(*words);
  }
  out.compileMs = median(times);
  mxc::Diagnostics diagnostics;
  auto optimized = mxc::spirv::compile(source, {.optimize = true, .reflection = nullptr, .specialization = {}}, diagnostics);
  if (!optimized) {
    out.error = diagnostics.format();
    return out;
  }
  out.optimized = mxc::spirv::instructionCount(*optimized);
  return out;
}

json figures(const ModuleFigures& m) {
  json j = {{"instructions", m.instructions}, {"optimized", m.optimized}, {"glslang_ms", m.compileMs}};
  if (!m.error.empty()) j["error"] = m.error;
  return j;
}

/// mxc from the file to GLSL, timed (median of `repeat`), then the GLSL's SPIR-V figures.
/// `shader` and `words` receive the raster shader and its plain module, for rendering.
json measureMxc(const mxc::lib::LibraryStack& libraries, std::unique_ptr<mxc::Workspace>& workspace, const fs::path& file,
                const std::string& material, mxc::Accuracy accuracy, int repeat, mxc::glsl::MaterialShader& shader,
                std::vector<uint32_t>& words) {
  std::vector<double> frontEnd;
  // A fresh workspace each time (a second load of one path would be served from the loader's
  // cache); the caller keeps the last, whose sources the shader's locations point into.
  for (int r = 0; r < repeat; ++r) {
    workspace = std::make_unique<mxc::Workspace>();
    const auto start = Clock::now();
    mxc::CompileRequest request;
    request.document = file;
    request.libraries = &libraries;
    request.material = material;
    request.accuracy = accuracy;
    mxc::Compiler compiler(*workspace, request);
    std::vector<mxc::ir::Material>& materials = compiler.materials();
    if (workspace->diagnostics.hasErrors()) return {{"error", workspace->diagnostics.format()}};
    if (materials.empty()) return {{"error", "no material named " + material}};
    shader = compiler.shader(materials.front());
    frontEnd.push_back(msSince(start));
  }
  ModuleFigures fragment = compileStage(shader.glsl, repeat);
  words = std::move(fragment.words);
  return {{"to_glsl_ms", median(frontEnd)},
          {"glsl_lines", shader.glsl.origins.size()},
          {"fragment", figures(fragment)},
          {"to_spirv_ms", median(frontEnd) + fragment.compileMs}};
}

json measureMaterialX(const json& entry, int repeat) {
  mxc::spirv::GlslSource vertex{readText(entry.at("vertex").get<std::string>()), mxc::spirv::Stage::Vertex,
                                "MaterialX vertex stage", {}};
  mxc::spirv::GlslSource pixel{readText(entry.at("pixel").get<std::string>()), mxc::spirv::Stage::Fragment,
                               "MaterialX pixel stage", {}};
  const ModuleFigures v = compileStage(vertex, repeat);
  const ModuleFigures p = compileStage(pixel, repeat);
  size_t lines = static_cast<size_t>(std::count(pixel.text.begin(), pixel.text.end(), '\n'));
  return {{"vertex", figures(v)}, {"fragment", figures(p)}, {"glsl_lines", lines}};
}

/// The image difference over pixels both renders cover fully: per pixel, the summed absolute
/// RGB difference over MaterialX's summed RGB (floored at 0.03, a dark grey, so that black
/// pixels do not divide by zero); its mean and 99th percentile.
json difference(const mxc::rt::RgbaImage& ours, const mxc::rt::RgbaImage& theirs) {
  std::vector<double> errors;
  double brightness = 0.0;  // MaterialX's mean summed RGB over the compared pixels
  for (size_t p = 0; p + 3 < ours.pixels.size() && p + 3 < theirs.pixels.size(); p += 4) {
    if (ours.pixels[p + 3] < 0.999f || theirs.pixels[p + 3] < 0.999f) continue;
    double diff = 0.0, base = 0.0;
    for (size_t c = 0; c < 3; ++c) {
      diff += std::abs(double(ours.pixels[p + c]) - double(theirs.pixels[p + c]));
      base += double(theirs.pixels[p + c]);
    }
    errors.push_back(diff / std::max(base, 0.03));  // floored: never a division by zero
    brightness += base;
  }
  if (errors.empty()) return {{"pixels", 0}};
  double mean = 0.0;
  for (double e : errors) mean += e;
  mean /= double(errors.size());
  std::sort(errors.begin(), errors.end());
  const double p99 = errors[std::min(errors.size() - 1, errors.size() * 99 / 100)];
  return {{"pixels", errors.size()}, {"mean", mean}, {"p99", p99}, {"brightness", brightness / double(errors.size())}};
}

struct RenderRig {
  mxc::rt::VulkanContext context;
  mxc::rt::AlbedoTables tables{context};
  mxc::rt::Renderer renderer{context, tables};
  mxc::rt::Mesh sphere = mxc::rt::makeSphere();
  mxc::rt::RenderSettings settings;
};

/// Both shaders on the same sphere, camera and light.
json renderBoth(RenderRig& rig, const json& entry, const mxc::glsl::MaterialShader& ours,
                const std::vector<uint32_t>& ourWords, const fs::path& images) {
  const std::string name = entry.at("name");
  const fs::path folder = fs::path(entry.at("mtlx").get<std::string>()).parent_path();
  json out;
  mxc::Diagnostics diagnostics;
  mxc::rt::MaterialResources resources(rig.context, ours.interface, folder, diagnostics);
  std::vector<std::string> warnings;
  for (const mxc::Diagnostic& d : diagnostics.all()) warnings.push_back(d.format());
  mxc::rt::RenderResult mine = rig.renderer.render(rig.sphere, resources, ours.interface, ourWords, rig.settings);
  auto loaded = mxc::cli::MaterialXShader::load(readText(entry.at("vertex").get<std::string>()),
                                                  readText(entry.at("pixel").get<std::string>()),
                                                  mxc::cli::parseMaterialXUniforms(readText(entry.at("uniforms").get<std::string>())), folder);
  if (auto* error = std::get_if<std::string>(&loaded)) return {{"error", *error}};
  mxc::rt::RenderResult theirs =
      std::get<mxc::cli::MaterialXShader>(loaded).render(rig.context, rig.renderer, rig.sphere, rig.settings, warnings);
  out["mxc_ms_per_frame"] = mine.msPerFrame;
  out["materialx_ms_per_frame"] = theirs.msPerFrame;
  out["difference"] = difference(mine.image, theirs.image);
  out["warnings"] = warnings;
  if (!images.empty()) {
    fs::create_directories(images);
    for (auto [suffix, image] : {std::pair{"mxc", &mine.image}, std::pair{"materialx", &theirs.image}}) {
      const fs::path png = images / fmt::format("{}_{}.png", name, suffix);
      if (auto error = mxc::rt::writeImage(png, *image)) out["warnings"].push_back(*error);
      out[std::string(suffix) + "_image"] = png.string();
    }
  }
  const auto validation = rig.context.validationMessages();
  if (!validation.empty()) out["validation"] = validation;
  rig.context.clearValidationMessages();
  return out;
}

}  // namespace

static int run(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: compare_bench MANIFEST.json RESULTS.json [--repeat N] [--size N] [--frames N] [--images DIR] "
                 "[--accuracy TIER]\n");
    return 2;
  }
  int repeat = 5;
  uint32_t size = 256, frames = 16;
  fs::path images;
  mxc::Accuracy accuracy = mxc::Accuracy::Balanced;
  for (int i = 3; i + 1 < argc; ++i) {
    if (!std::strcmp(argv[i], "--accuracy")) {
      std::optional<mxc::Accuracy> tier = mxc::parseAccuracy(argv[i + 1]);
      if (!tier) {
        std::fprintf(stderr, "compare_bench: --accuracy %s: not a tier\n", argv[i + 1]);
        return 2;
      }
      accuracy = *tier;
    }
    if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--size")) size = static_cast<uint32_t>(std::max(8, std::atoi(argv[i + 1])));
    if (!std::strcmp(argv[i], "--frames")) frames = static_cast<uint32_t>(std::max(1, std::atoi(argv[i + 1])));
    if (!std::strcmp(argv[i], "--images")) images = argv[i + 1];
  }
  json manifest;
  try {
    manifest = json::parse(readText(argv[1]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare_bench: %s: %s\n", argv[1], e.what());
    return 1;
  }

  const auto libraryStart = Clock::now();
  mxc::Workspace library;
  library.loadLibraries();
  const double libraryMs = msSince(libraryStart);

  RenderRig rig;
  rig.settings.width = rig.settings.height = size;
  rig.settings.frames = frames;
  rig.settings.environment = mxc::rt::Environment::None;
  // One directional light from the upper left front, irradiance 3 at normal incidence.
  rig.settings.lights.push_back(
      {mxc::rt::Light::Kind::Directional, glm::normalize(glm::vec3(-1.0f, 1.2f, 1.5f)), glm::vec3(1.0f), 3.0f});

  json results = {{"mxc_library_ms", libraryMs},
                  {"repeat", repeat},
                  {"accuracy", mxc::accuracyName(accuracy)},
                  {"device", rig.context.deviceName()},
                  {"size", size},
                  {"frames", frames},
                  {"materials", json::array()}};
  for (const json& entry : manifest.at("materials")) {
    const std::string name = entry.at("name");
    std::fprintf(stderr, "compare_bench: %s\n", name.c_str());
    json row = {{"name", name}};
    mxc::glsl::MaterialShader shader;
    std::vector<uint32_t> words;
    std::unique_ptr<mxc::Workspace> workspace;
    row["mxc"] = measureMxc(library.libraries, workspace, entry.at("mtlx").get<std::string>(), entry.value("material", ""),
                            accuracy, repeat, shader, words);
    row["materialx"] = measureMaterialX(entry, repeat);
    if (!words.empty()) {  // else row["mxc"] says why
      try {
        row["render"] = renderBoth(rig, entry, shader, words, images);
      } catch (const std::exception& e) {
        row["render"] = {{"error", e.what()}};
      }
    }
    results["materials"].push_back(row);
  }
  const std::string out = argv[2];
  const std::string temporary = out + ".tmp";
  {
    std::ofstream file(temporary);
    file << results.dump(2) << "\n";
    if (!file) {
      std::fprintf(stderr, "compare_bench: cannot write %s\n", temporary.c_str());
      return 3;
    }
  }
  fs::rename(temporary, out);
  return 0;
}

int main(int argc, char** argv) {
  int status = 0;
  mxc::runWithLargeStack([&] { status = run(argc, argv); });  // as the CLI runs its commands
  return status;
}
