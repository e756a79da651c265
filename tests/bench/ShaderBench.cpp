// Shader compile and render cost: for open_pbr_default, open_pbr_carpaint and a rough white
// metal and rough glass, on every accuracy tier, the time from the .mtlx file to a validated
// SPIR-V module (front end, GLSL, glslang, SPIRV-Tools), the module's instruction count (plain
// and optimised), and the frame time of the sphere renderer, against a flat-colour fragment
// shader measured in the same run on the same device, and each tier's frame time against the
// fast tier's; and the time per BSDF evaluation (f cos and pdf of one direction pair) in the
// compute harness, against a white Lambertian's in the same run.
//
//   build/tests/bench/shader_bench [--size N] [--frames N] [--repeat N] [--pairs N] [--materials N]
//
// --materials N measures the first N of the four materials only (the smoke test runs one).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "compiler/driver/Compiler.h"
#include "runtime/Evaluator.h"
#include "runtime/Renderer.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Compiled {
  std::unique_ptr<mxc::Workspace> workspace;
  mxc::glsl::MaterialShader shader;
  std::vector<uint32_t> words;
  mxc::glsl::MaterialShader evalShader;  // the same material's f cos compute shader
  std::vector<uint32_t> evalWords;
  double frontEndMs = 0.0;  // parse, resolve, lower, passes, GLSL
  double spirvMs = 0.0;     // glslang and SPIRV-Tools validation
};

/// One compile from the file, with the library already loaded (as in a running tool). The
/// workspace is kept with the result: the shader's locations point into its sources.
Compiled compileFile(const mxc::lib::LibraryStack& libraries, const fs::path& file, mxc::Accuracy accuracy,
                     const std::vector<std::pair<std::string, std::string>>& overrides) {
  Compiled out;
  out.workspace = std::make_unique<mxc::Workspace>();
  const auto start = Clock::now();
  mxc::CompileRequest request;
  request.document = file;
  request.libraries = &libraries;
  request.accuracy = accuracy;
  request.lowering.overrides = overrides;
  mxc::Compiler compiler(*out.workspace, request);
  out.shader = compiler.shader(compiler.materials().at(0));
  out.frontEndMs = msSince(start);
  const auto glslang = Clock::now();
  auto words = compiler.spirv(out.shader);
  out.spirvMs = msSince(glslang);
  if (!words) {
    std::fprintf(stderr, "%s", out.workspace->diagnostics.format().c_str());
    std::exit(1);
  }
  out.words = std::move(*words);
  out.evalShader = compiler.shader(compiler.materials().at(0), mxc::glsl::ShaderKind::Eval);
  auto evalWords = compiler.spirv(out.evalShader);
  if (!evalWords) {
    std::fprintf(stderr, "%s", out.workspace->diagnostics.format().c_str());
    std::exit(1);
  }
  out.evalWords = std::move(*evalWords);
  return out;
}

/// The baseline: a fragment shader that writes one colour, with the renderer's interface.
Compiled flatShader() {
  Compiled out;
  out.shader.glsl.stage = mxc::spirv::Stage::Fragment;
  out.shader.glsl.name = "flat colour";
  out.shader.glsl.text =
      "#version 450\nlayout(location = 0) out vec4 outColor;\n"
      "void main() { outColor = vec4(0.18, 0.18, 0.18, 1.0); }\n";
  out.shader.interface.parameterBytes = 16;
  mxc::Diagnostics diagnostics;
  out.words = *mxc::spirv::compile(out.shader.glsl, {}, diagnostics);
  return out;
}

size_t optimizedCount(const Compiled& c) {
  mxc::Diagnostics diagnostics;
  mxc::CompileRequest request;
  request.optimize = true;
  auto words = mxc::compileShader(c.shader, request, diagnostics);
  return words ? mxc::spirv::instructionCount(*words) : 0;
}

}  // namespace

int main(int argc, char** argv) {
  uint32_t size = 512, frames = 16;
  int repeat = 5;
  uint32_t pairCount = 1u << 20;
  size_t materialCount = 4;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--pairs")) pairCount = static_cast<uint32_t>(std::max(1, std::atoi(argv[i + 1])));
    if (!std::strcmp(argv[i], "--size")) size = static_cast<uint32_t>(std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--frames")) frames = static_cast<uint32_t>(std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(1, std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--materials")) materialCount = static_cast<size_t>(std::max(1, std::atoi(argv[i + 1])));
  }
  const fs::path shared = MXC_SHARED_DIR;
  const fs::path defaultFile = shared / "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx";
  struct Case {
    std::string name;
    fs::path file;
    std::vector<std::pair<std::string, std::string>> overrides;
  };
  const Case cases[] = {
      {"open_pbr_default", defaultFile, {}},
      {"open_pbr_carpaint", shared / "corpus/materialx/examples/OpenPbr/open_pbr_carpaint.mtlx", {}},
      {"rough_metal", defaultFile, {{"base_metalness", "1"}, {"specular_roughness", "0.6"}}},
      {"rough_glass", defaultFile, {{"transmission_weight", "1"}, {"specular_roughness", "0.5"}}},
  };
  mxc::Workspace library;
  library.loadLibraries();
  mxc::Diagnostics& diagnostics = library.diagnostics;

  mxc::rt::VulkanContext context;
  mxc::rt::AlbedoTables tables(context);
  mxc::rt::Renderer renderer(context, tables);
  const mxc::rt::Mesh sphere = mxc::rt::makeSphere();
  mxc::rt::RenderSettings settings;
  settings.width = settings.height = size;
  settings.frames = frames;
  settings.lights.push_back({mxc::rt::Light::Kind::Directional, glm::normalize(glm::vec3(-1, 1.2f, 1.5f)), glm::vec3(1), 2});
  auto frameMs = [&](const Compiled& c) {
    mxc::rt::MaterialResources resources(context, c.shader.interface, {}, diagnostics);
    std::vector<double> times;
    for (int r = 0; r < std::max(1, repeat / 2); ++r) {
      times.push_back(renderer.render(sphere, resources, c.shader.interface, c.words, settings).msPerFrame);
    }
    return median(times);
  };

  // Direction pairs over the sphere (a fixed sequence), the same for every material.
  std::vector<mxc::rt::DirectionPair> pairs;
  for (uint32_t k = 0; k < pairCount; ++k) {
    auto direction = [](float u, float v) {  // uniform on the sphere
      const float z = 1.0f - 2.0f * u, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 6.2831853f * v;
      return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    const float a = float(k) * 0.6180339887f, b = float(k) * 0.7548776662f, c = float(k) * 0.5698402910f;
    pairs.push_back({direction(a - std::floor(a), b - std::floor(b)), direction(c - std::floor(c), 0.5f * (a - std::floor(a)))});
  }
  auto nsPerEval = [&](const Compiled& c) {
    mxc::rt::MaterialResources resources(context, c.evalShader.interface, {}, diagnostics);
    mxc::rt::MaterialEvaluator evaluator(context, tables, resources, c.evalShader.interface, c.evalWords);
    evaluator.evaluate(pairs);  // the first dispatch pays the pipeline's compilation
    std::vector<double> times;
    for (int r = 0; r < std::max(3, repeat); ++r) {
      const auto start = Clock::now();
      evaluator.evaluate(pairs);
      times.push_back(msSince(start) * 1e6 / double(pairs.size()));
    }
    return median(times);
  };

  std::printf("device: %s; %ux%u, %u frames of 1 sample; %zu BSDF evaluations per dispatch; median of runs\n\n",
              context.deviceName().c_str(), size, size, frames, pairs.size());
  double lambertNs = 0.0;
  {
    Compiled lambert = compileFile(library.libraries, defaultFile, mxc::Accuracy::Balanced,
                                   {{"base_color", "1, 1, 1"}, {"specular_weight", "0"}});
    lambertNs = nsPerEval(lambert);
    std::printf("white Lambertian (EON, no specular): %.1f ns per evaluation (the baseline of 'x lambert')\n\n",
                lambertNs);
  }
  const Compiled flat = flatShader();
  const double flatMs = frameMs(flat);
  std::printf("%-28s %10s %10s %10s %11s %10s %9s %7s %7s %8s %9s %7s\n", "material (tier)", "front end", "glslang",
              "total", "SPIR-V ops", "optimised", "ms/frame", "x flat", "x fast", "ns/eval", "x lambert", "x fast");
  std::printf("%-28s %10s %10s %10s %11zu %10zu %9.2f %7.2f %7s %8s %9s %7s\n", "flat colour", "-", "-", "-",
              mxc::spirv::instructionCount(flat.words), optimizedCount(flat), flatMs, 1.0, "-", "-", "-", "-");
  for (const Case& c : cases) {
    if (materialCount-- == 0) break;
    double fastMs = 0.0, fastNs = 0.0;
    for (mxc::Accuracy accuracy : mxc::kAccuracies) {
      std::vector<double> front, spirv, total;
      Compiled last;
      for (int r = 0; r < repeat; ++r) {
        last = compileFile(library.libraries, c.file, accuracy, c.overrides);
        front.push_back(last.frontEndMs);
        spirv.push_back(last.spirvMs);
        total.push_back(last.frontEndMs + last.spirvMs);
      }
      const double ms = frameMs(last);
      const double ns = nsPerEval(last);
      if (accuracy == mxc::Accuracy::Fast) {
        fastMs = ms;
        fastNs = ns;
      }
      const std::string label = c.name + " (" + std::string(mxc::accuracyName(accuracy)) + ")";
      std::printf("%-28s %8.2fms %8.2fms %8.2fms %11zu %10zu %9.2f %7.2f %7.2f %8.1f %9.2f %7.2f\n", label.c_str(),
                  median(front), median(spirv), median(total), mxc::spirv::instructionCount(last.words),
                  optimizedCount(last), ms, ms / flatMs, fastMs > 0.0 ? ms / fastMs : 0.0, ns, ns / lambertNs,
                  fastNs > 0.0 ? ns / fastNs : 0.0);
    }
  }
  return 0;
}
