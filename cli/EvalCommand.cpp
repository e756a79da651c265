#include "cli/Verbosity.h"
#include "compiler/common/JsonText.h"
#include "compiler/glsl/Contract.h"
#include "cli/EvalCommand.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/OutputSet.h"
#include "cli/ExitCode.h"
#include "cli/Harness.h"
#include "cli/MaterialPipeline.h"
#include "compiler/common/InputFile.h"
#include "runtime/Evaluator.h"

namespace mxc::cli {

namespace {

/// Reads rows "wo_x,wo_y,wo_z,wi_x,wi_y,wi_z" (blank lines, '#' comments and one header line of
/// names allowed). Errors name file:line:column.
bool readDirections(const std::string& path, std::vector<rt::DirectionPair>& rows) {
  constexpr size_t kMaxBytes = size_t{1} << 30;
  auto bytes = readInputFile(path, kMaxBytes);
  if (auto* why = std::get_if<1>(&bytes)) {
    std::fprintf(stderr, "error: cannot read the directions '%s': %s\n", path.c_str(), why->c_str());
    return false;
  }
  std::istringstream in(std::move(std::get<0>(bytes)));
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    if (rows.empty() && std::isalpha(static_cast<unsigned char>(line[first]))) continue;  // a header
    float v[6];
    size_t pos = 0;
    for (int k = 0; k < 6; ++k) {
      const size_t end = std::min(line.find(',', pos), line.size());
      const std::string field = line.substr(pos, end - pos);
      size_t used = 0;
      bool ok = true;
      try {
        v[k] = std::stof(field, &used);
      } catch (const std::exception&) {
        ok = false;
      }
      ok = ok && std::isfinite(v[k]) && field.find_first_not_of(" \t", used) == std::string::npos;
      if (!ok) {
        std::fprintf(stderr, "%s:%d:%zu: error: expected a number as value %d of 6 (wo_x,wo_y,wo_z,wi_x,wi_y,wi_z)\n",
                     path.c_str(), lineNo, pos + 1, k + 1);
        return false;
      }
      if (k < 5 && end == line.size()) {
        std::fprintf(stderr, "%s:%d:%zu: error: expected 6 values, found %d\n", path.c_str(), lineNo, line.size() + 1,
                     k + 1);
        return false;
      }
      pos = end + 1;
    }
    if (pos <= line.size()) {
      std::fprintf(stderr, "%s:%d:%zu: error: more than 6 values\n", path.c_str(), lineNo, pos);
      return false;
    }
    glm::vec3 wo(v[0], v[1], v[2]), wi(v[3], v[4], v[5]);
    // Directions are normalised here; a zero vector has none.
    if (glm::dot(wo, wo) < 1e-12f || glm::dot(wi, wi) < 1e-12f) {
      std::fprintf(stderr, "%s:%d:1: error: a direction of zero length\n", path.c_str(), lineNo);
      return false;
    }
    rows.push_back({glm::normalize(wo), glm::normalize(wi)});
  }
  return true;
}

/// Declares a command's one report (`-o`, or standard output) and checks it is not an input.
/// Returns kOk or the exit code to stop with (the error printed).
int declareReport(OutputSet& outputs, const std::string& output, const MaterialPipeline& pipeline,
                  const std::string& dirs = {}) {
  if (printError(outputs.declare(output.empty() ? "-" : output, "-o"))) return kOutputFailed;
  if (printError(pipeline.checkOutputsAreNotInputs(outputs))) return kUsage;
  if (!dirs.empty() && printError(outputs.checkNotInput(dirs, "the --dirs file"))) return kUsage;
  return kOk;
}

/// Stages and commits the report; kOk or kOutputFailed (the error printed).
int writeReport(OutputSet& outputs, const std::string& output, std::string report) {
  std::optional<std::string> error = outputs.stage(output.empty() ? "-" : output, std::move(report));
  if (!error) error = outputs.commit();
  return printError(error) ? kOutputFailed : kOk;
}

/// A vec3 as a JSON array.
nlohmann::json vec(glm::vec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); }

/// True when every lobe of `material` is a delta: microfacet lobes whose alpha is a constant
/// below glsl::kDeltaAlpha, and nothing else that scatters.
bool everyLobeIsDelta(const ir::Material& material) {
  if (material.interfaces.empty()) return false;
  for (const ir::Interface& i : material.interfaces) {
    const bool microfacet = i.kind == ir::InterfaceKind::Dielectric || i.kind == ir::InterfaceKind::Conductor ||
                            i.kind == ir::InterfaceKind::Schlick;
    if (!microfacet) return false;
    const ir::ExprId alpha = i.slots.value(ir::Slot::Alpha);
    if (!material.exprs.isConstant(alpha)) return false;
    for (float a : material.exprs.constantComponents(alpha)) {
      if (!(a < glsl::kDeltaAlpha)) return false;
    }
  }
  return true;
}

}  // namespace

/// eval's walks per direction pair in the reference tier: its relative noise is then about
/// 1/sqrt(1024) = 3% of a walk's.
constexpr uint32_t kEvalReferenceSamples = 1024;

int runEval(const EvalOptions& options) {
  std::vector<rt::DirectionPair> rows;
  if (!readDirections(options.dirs, rows)) return kInvalidDocument;
  Session session;
  MaterialPipeline pipeline(session);
  // The reference tier's walks per pair: one per dispatch (rt::MaterialKernel says why), as many
  // dispatches as walks.
  MaterialOptions materials = options.materials;
  const uint32_t walks = materials.referenceSamples > 0 ? uint32_t(materials.referenceSamples) : kEvalReferenceSamples;
  const uint32_t dispatches = materials.accuracy == Accuracy::Reference ? walks : 1;
  materials.referenceSamples = 1;
  CompileRequest request;
  request.document = options.file;
  if (int code = pipeline.run(std::move(request), materials); code != kOk) return code;
  OutputSet outputs;
  if (int code = declareReport(outputs, options.output, pipeline, options.dirs); code != kOk) return code;
  Device device(options.device);
  rt::AlbedoTables* tables = device.tables();
  if (!tables) return kNoDevice;
  std::string csv = "material,row,fcos_r,fcos_g,fcos_b,pdf\n";
  for (const ir::Material& material : pipeline.materials()) {
    auto program = prepareMaterial(pipeline, session, *device.context(), material, glsl::ShaderKind::Eval);
    if (!program) return kInvalidDocument;
    rt::MaterialEvaluator evaluator(*device.context(), *tables, *program->resources, program->shader.interface,
                                    program->spirv);
    std::vector<glm::vec4> values = evaluator.evaluate(rows, dispatches);
    if (everyLobeIsDelta(material) && !quiet()) {
      std::fprintf(stderr,
                   "note: %s: every lobe is a delta (roughness 0): f cos is zero for almost every pair of directions, "
                   "so eval prints zeros; 'mxc furnace' measures what it reflects and transmits\n",
                   material.name.c_str());
    }
    for (size_t i = 0; i < values.size(); ++i) {
      csv += fmt::format("{},{},{:.7g},{:.7g},{:.7g},{:.7g}\n", material.name, i + 1, values[i].x, values[i].y,
                         values[i].z, values[i].w);
    }
  }
  if (!device.checkValidation()) return kInvalidDocument;
  return writeReport(outputs, options.output, std::move(csv));
}

int runFurnace(const FurnaceOptions& options) {
  Session session;
  MaterialPipeline pipeline(session);
  CompileRequest request;
  request.document = options.file;
  if (int code = pipeline.run(std::move(request), options.materials); code != kOk) return code;
  OutputSet outputs;
  if (int code = declareReport(outputs, options.output, pipeline); code != kOk) return code;
  Device device(options.device);
  rt::AlbedoTables* tables = device.tables();
  if (!tables) return kNoDevice;
  // View angles theta_k = 90 deg * k / N, k = 0..N-1: normal incidence first, never exactly grazing.
  std::vector<glm::vec3> views;
  std::vector<double> thetas;
  for (int k = 0; k < options.angles; ++k) {
    const double theta = 0.5 * M_PI * k / options.angles;
    thetas.push_back(theta);
    views.emplace_back(static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(std::cos(theta)));
  }
  nlohmann::json report{{"document", options.file},
                        {"samples", options.samples},
                        {"device", device.context()->deviceName()},
                        {"materials", nlohmann::json::array()}};
  Progress progress(pipeline.materials().size());
  for (const ir::Material& material : pipeline.materials()) {
    auto program = prepareMaterial(pipeline, session, *device.context(), material, glsl::ShaderKind::Furnace);
    if (!program) return kInvalidDocument;
    rt::FurnaceEstimator furnace(*device.context(), *tables, *program->resources, program->shader.interface,
                                 program->spirv);
    std::vector<rt::Albedo> albedo =
        furnace.estimate(views, static_cast<uint32_t>(options.samples), static_cast<uint32_t>(options.seed));
    progress.step(material.name);
    nlohmann::json m{{"name", material.name}, {"angles", nlohmann::json::array()}};
    for (size_t k = 0; k < albedo.size(); ++k) {
      m["angles"].push_back({{"theta_deg", thetas[k] * 180.0 / M_PI},
                             {"mu", std::cos(thetas[k])},
                             {"reflected", vec(albedo[k].reflected)},
                             {"transmitted", vec(albedo[k].transmitted)},
                             {"total", vec(albedo[k].total())},
                             {"reflected_error", vec(albedo[k].reflectedError)},
                             {"transmitted_error", vec(albedo[k].transmittedError)}});
    }
    report["materials"].push_back(std::move(m));
  }
  if (!device.checkValidation()) return kInvalidDocument;
  bool lossy = false;
  std::string text = jsonText(report, 2, &lossy) + "\n";
  if (lossy) std::fprintf(stderr, "warning: %s\n", notUtf8Warning("the JSON report").c_str());
  return writeReport(outputs, options.output, std::move(text));
}

}  // namespace mxc::cli
