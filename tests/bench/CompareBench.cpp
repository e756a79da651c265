// The C++ half of the side-by-side comparison with MaterialX (tests/bench/materialx_compare.py
// runs it). For each material of a manifest written by the script, with MaterialX's Vulkan GLSL
// already generated and timed there:
//   - times mxc from the .mtlx file to GLSL (parse, resolve, lower, passes, GLSL) and from GLSL
//     to a validated SPIR-V module, with mxc's library loaded once beforehand (reported apart,
//     as the script reports MaterialX's library load apart);
//   - compiles both sides' GLSL with the same glslang and SPIRV-Tools (MaterialX's vertex and
//     pixel stages; mxc's raster fragment shader) and counts SPIR-V instructions before and
//     after SPIRV-Tools' performance passes.
// Writes the figures as JSON for the script's report.
//
//   build/tests/bench/compare_bench MANIFEST.json RESULTS.json [--repeat N]
//
// MANIFEST: {"materials": [{"name", "mtlx", "material", "vertex", "pixel"}]} (paths to files).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compiler/common/LargeStack.h"
#include "compiler/document/DocumentLoader.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/ir/Effects.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/library/LibraryStack.h"
#include "compiler/lower/Lowering.h"
#include "compiler/resolve/Resolver.h"
#include "compiler/spirv/SpirvCompiler.h"

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
  }
  out.compileMs = median(times);
  mxc::Diagnostics diagnostics;
  auto optimized = mxc::spirv::compile(source, {true}, diagnostics);
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
json measureMxc(mxc::lib::LibraryStack& libraries, mxc::SourceManager& sources, const fs::path& file,
                const std::string& material, int repeat) {
  std::vector<double> frontEnd;
  mxc::glsl::MaterialShader shader;
  for (int r = 0; r < repeat; ++r) {
    mxc::Diagnostics diagnostics;
    const auto start = Clock::now();
    mxc::doc::DocumentLoader loader(sources, diagnostics);
    const mxc::doc::Document* d = loader.loadFile(file);
    if (!d || diagnostics.hasErrors()) return {{"error", diagnostics.format()}};
    auto resolved = mxc::resolve::resolveDocument(*d, libraries.top(), diagnostics);
    std::vector<mxc::ir::Material> materials = mxc::lower::lowerDocument(resolved, {}, diagnostics);
    if (diagnostics.hasErrors()) return {{"error", diagnostics.format()}};
    auto chosen = std::find_if(materials.begin(), materials.end(),
                               [&](const mxc::ir::Material& m) { return material.empty() || m.name == material; });
    if (chosen == materials.end()) return {{"error", "no material named " + material}};
    mxc::ir::runPasses(*chosen);
    mxc::ir::summarizeEffects(*chosen);
    shader = mxc::glsl::buildMaterialShader(*chosen, mxc::glsl::ShaderKind::Raster);
    frontEnd.push_back(msSince(start));
  }
  const ModuleFigures fragment = compileStage(shader.glsl, repeat);
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

}  // namespace

static int run(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: compare_bench MANIFEST.json RESULTS.json [--repeat N]\n");
    return 2;
  }
  int repeat = 5;
  for (int i = 3; i + 1 < argc; ++i) {
    if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
  }
  json manifest;
  try {
    manifest = json::parse(readText(argv[1]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compare_bench: %s: %s\n", argv[1], e.what());
    return 1;
  }

  mxc::SourceManager sources;
  mxc::Diagnostics diagnostics;
  const auto libraryStart = Clock::now();
  mxc::lib::LibraryStack libraries(sources, diagnostics);
  libraries.addBuiltin();
  const double libraryMs = msSince(libraryStart);

  json results = {{"mxc_library_ms", libraryMs}, {"repeat", repeat}, {"materials", json::array()}};
  for (const json& entry : manifest.at("materials")) {
    const std::string name = entry.at("name");
    std::fprintf(stderr, "compare_bench: %s\n", name.c_str());
    json row = {{"name", name}};
    row["mxc"] = measureMxc(libraries, sources, entry.at("mtlx").get<std::string>(), entry.value("material", ""), repeat);
    row["materialx"] = measureMaterialX(entry, repeat);
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
