#include "cli/CompileCommand.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cli/OutputSet.h"
#include "cli/ExitCode.h"
#include "cli/MaterialPipeline.h"
#include "compiler/glsl/ShaderBuilder.h"
#include "compiler/spirv/SpirvCompiler.h"

namespace mxc::cli {

namespace {

glsl::ShaderKind kindOf(const std::string& stage) {
  if (stage == "comp") return glsl::ShaderKind::Eval;
  if (stage == "furnace") return glsl::ShaderKind::Furnace;
  if (stage == "sample") return glsl::ShaderKind::Sample;
  return glsl::ShaderKind::Raster;
}

}  // namespace

int runCompile(const CompileOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Session session;
  MaterialPipeline pipeline(session);
  CompileRequest request;
  request.document = options.file;
  request.stage = kindOf(options.stage);
  request.optimize = options.optimize;
  if (int code = pipeline.run(std::move(request), options.materials); code != kOk) return code;
  Compiler& compiler = pipeline.compiler();
  const bool several = pipeline.materials().size() > 1;
  // Every output is declared and checked before anything is compiled or written.
  OutputSet outputs;
  for (const ir::Material& material : pipeline.materials()) {
    for (const auto& [path, option] : {std::pair{options.output, "-o"}, std::pair{options.glsl, "--glsl"}}) {
      if (path.empty()) continue;
      if (printError(outputs.declare(perMaterialPath(path, material.name, several), option))) return kOutputFailed;
    }
  }
  if (printError(outputs.checkDistinct()) || printError(pipeline.checkOutputsAreNotInputs(outputs))) return kUsage;
  // A module on standard output would be mixed with the summary lines.
  const bool quiet = options.quiet || options.output == "-" || options.glsl == "-";
  int result = kOk;
  for (const ir::Material& material : pipeline.materials()) {
    glsl::MaterialShader shader = compiler.shader(material);
    std::optional<std::vector<uint32_t>> words = compiler.spirv(shader);
    session.printDiagnostics();
    if (!options.glsl.empty()) {
      // The GLSL is produced even when glslang rejects it, so that the failing line can be read.
      const auto path = perMaterialPath(options.glsl, material.name, several);
      if (printError(outputs.stage(path, shader.glsl.text))) return kOutputFailed;
    }
    if (!words) {
      result = kInvalidDocument;
      continue;
    }
    if (!options.output.empty()) {
      std::string bytes(reinterpret_cast<const char*>(words->data()), words->size() * sizeof(uint32_t));
      const auto path = perMaterialPath(options.output, material.name, several);
      if (printError(outputs.stage(path, std::move(bytes)))) return kOutputFailed;
    }
    if (!quiet) {
      std::vector<std::string> lobes;
      shader.interface.lobeKinds.forEach([&](ir::LobeKind k) { lobes.emplace_back(ir::lobeKindName(k)); });
      std::sort(lobes.begin(), lobes.end());
      std::printf("%s: %s shader, %zu GLSL lines, %zu SPIR-V instructions; lobes %d (%s)%s%s\n", material.name.c_str(),
                  std::string(glsl::shaderKindName(kindOf(options.stage))).c_str(),
                  shader.glsl.origins.size(), spirv::instructionCount(*words), shader.interface.lobes,
                  fmt::format("{}", fmt::join(lobes, ", ")).c_str(),
                  shader.interface.textures.empty() ? "" : fmt::format("; {} texture(s)", shader.interface.textures.size()).c_str(),
                  shader.interface.parameters.size() > 3
                      ? fmt::format("; {} parameter(s)", shader.interface.parameters.size() - 3).c_str()
                      : "");
    }
  }
  // All or nothing: a SPIR-V module that was not produced leaves every output as it was.
  if (!outputs.complete()) {
    std::fprintf(stderr, "error: no output written: a shader did not compile\n");
  } else if (printError(outputs.commit())) {
    return kOutputFailed;
  }
  if (!quiet) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("compiled %zu material(s) in %.1f ms\n", pipeline.materials().size(), ms);
  }
  return result;
}

}  // namespace mxc::cli
