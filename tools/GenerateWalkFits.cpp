// mxc-generate-walk-fits: measures what the reference tier's random walk
// (compiler/glsl/library/mxc_walk.glsl) makes of the physical parameters behind the colours
// OpenPBR defines by what is observed, and writes the walk's tables that turn those colours back
// into them (generated/tables/mxc_walk_tables.bin; what they hold and why:
// compiler/glsl/WalkTables.h):
//
// - the walk's rough dielectric seen from outside: its reflectance R(mu) at Gauss-Legendre view
//   cosines, integrated to the cosine-weighted R_out; energy balance in diffuse light (a
//   lossless reciprocal interface passes as much flux in as out) gives the reflectance from
//   inside, r_i = 1 - (1 - R_out) / eta^2;
// - the same reflectance, all orders of scattering, on the albedo tables' grid of view cosine
//   and roughness, which the balanced tier's multiple-scattering compensation divides between
//   reflection and transmission by;
// - a semi-infinite medium of single-scattering albedo omega and Henyey-Greenstein g under that
//   interface, at normal incidence: the albedo E, and E_spec with omega = 0 (nothing comes back
//   out of the medium), so that C = (E - E_spec) / (1 - E_spec); over van de Hulst's
//   s = sqrt((1 - omega) / (1 - omega g)), fitted by van de Hulst's form with free coefficients
//   (tools/WalkFits.cpp) and inverted at the tables' colours.
//
// The media are OpenPBR's translucent base with a scattering depth, whose coefficients are the
// raw ones (mu_t = -ln(transmission_color) / depth, mu_s = transmission_scatter / depth), so
// that nothing of the tables being made enters the measurement; the inputs are uniforms of one
// shader per kind, set between estimates.
//
//   mxc-generate-walk-fits measure [FOLDER]        measure (about 40 minutes on lavapipe) and tabulate
//   mxc-generate-walk-fits measure-KIND [FOLDER]   measure one kind again (interface, reflectance,
//                                                  medium), keep the others from the CSV, tabulate
//   mxc-generate-walk-fits fit [FOLDER]            tabulate again from FOLDER/mxc_walk_measurements.csv
//
// FOLDER defaults to generated/tables. Run by scripts/generate-tables --walk; outputs are committed.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compiler/common/OutputFile.h"
#include "compiler/driver/Compiler.h"
#include "compiler/glsl/AlbedoTableFile.h"
#include "compiler/glsl/Bindings.h"
#include "compiler/glsl/WalkTables.h"
#include "runtime/AlbedoTables.h"
#include "runtime/Evaluator.h"
#include "runtime/MaterialResources.h"
#include "runtime/VulkanContext.h"
#include "tools/WalkFits.h"

namespace {

using mxc::tools::WalkMeasurement;

/// One OpenPBR material of the reference tier, compiled once as a furnace shader whose named
/// inputs are uniforms, set between estimates.
class WalkFurnace {
 public:
  WalkFurnace(mxc::rt::VulkanContext& context, const mxc::rt::AlbedoTables& tables, const std::string& inputs,
              const std::vector<std::string>& parameters) {
    if (!workspace_.loadLibraries()) throw std::runtime_error("the built-in library did not load");
    mxc::CompileRequest request;
    request.document = "walk-fits.mtlx";
    request.text = "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n"
                   "  <open_pbr_surface name=\"s\" type=\"surfaceshader\">\n" +
                   inputs +
                   "  </open_pbr_surface>\n  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" "
                   "type=\"surfaceshader\" nodename=\"s\" /></surfacematerial>\n</materialx>\n";
    request.lowering.parameters = parameters;
    request.accuracy = mxc::Accuracy::Reference;
    mxc::Compiler compiler(workspace_, request);
    std::vector<mxc::ir::Material>& materials = compiler.materials();
    if (materials.size() != 1) throw std::runtime_error("walk-fits: " + workspace_.diagnostics.format());
    shader_ = compiler.shader(materials.front(), mxc::glsl::ShaderKind::Furnace);
    std::optional<std::vector<uint32_t>> words = compiler.spirv(shader_);
    if (!words) throw std::runtime_error("walk-fits: " + workspace_.diagnostics.format());
    resources_ = std::make_unique<mxc::rt::MaterialResources>(context, shader_.interface, std::filesystem::path(),
                                                              workspace_.diagnostics);
    estimator_ = std::make_unique<mxc::rt::FurnaceEstimator>(context, tables, *resources_, shader_.interface, *words);
  }

  void set(const std::string& name, std::vector<float> value) {
    // The uniform of input NAME is p_NAME (compiler/glsl/ShaderInterface.cpp).
    if (!resources_->setParameter("p_" + name, value)) throw std::runtime_error("walk-fits: no uniform for " + name);
  }
  std::vector<mxc::rt::Albedo> estimate(const std::vector<glm::vec3>& views, uint32_t samples, uint32_t seed) {
    return estimator_->estimate(views, samples, seed);
  }

 private:
  mxc::Workspace workspace_;
  mxc::glsl::MaterialShader shader_;
  std::unique_ptr<mxc::rt::MaterialResources> resources_;
  std::unique_ptr<mxc::rt::FurnaceEstimator> estimator_;
};

std::string input(const char* name, const char* type, const std::string& value) {
  return fmt::format("    <input name=\"{}\" type=\"{}\" value=\"{}\" />\n", name, type, value);
}

/// The walk's rough dielectric, seen from outside: its reflectance at the cosines `mus`.
std::vector<WalkMeasurement> measureInterfaces(mxc::rt::VulkanContext& context, const mxc::rt::AlbedoTables& tables) {
  WalkFurnace furnace(context, tables,
                      input("transmission_weight", "float", "1") + input("specular_ior", "float", "1.5") +
                          input("specular_roughness", "float", "0.5"),
                      {"specular_ior", "specular_roughness"});
  std::vector<double> mus, weights;
  mxc::tools::gaussLegendre(mxc::tools::kInterfaceViews, mus, weights);
  std::vector<glm::vec3> views;
  for (double mu : mus) views.push_back(glm::vec3(float(std::sqrt(1.0 - mu * mu)), 0.0f, float(mu)));
  std::vector<WalkMeasurement> out;
  uint32_t seed = 1;
  for (uint32_t e = 0; e < mxc::glsl::kWalkEtaSteps; ++e) {
    const double eta = mxc::glsl::walkTableEta(int(e));
    for (uint32_t i = 0; i < mxc::glsl::kTableSize; ++i) {
      const double roughness = double(i) / (mxc::glsl::kTableSize - 1.0);
      furnace.set("specular_ior", {float(eta)});
      furnace.set("specular_roughness", {float(roughness)});
      std::vector<mxc::rt::Albedo> a = furnace.estimate(views, mxc::tools::kInterfaceSamples, seed++);
      for (size_t k = 0; k < views.size(); ++k) {
        out.push_back({"interface", eta, 0.0, roughness, mus[k], a[k].reflected.x, a[k].reflectedError.x});
      }
    }
    std::fprintf(stderr, "  interface eta %.3f measured\n", eta);
  }
  return out;
}

/// The walk's rough dielectric seen from outside, on the tables' grid: per IOR ratio and
/// roughness x = j / (n - 1) (alpha = x^2), its reflectance, all orders, at the view cosines
/// mu = (i / (n - 1))^2 (10^-4 for i = 0), the albedo tables' axes.
std::vector<WalkMeasurement> measureReflectance(mxc::rt::VulkanContext& context, const mxc::rt::AlbedoTables& tables) {
  WalkFurnace furnace(context, tables,
                      input("transmission_weight", "float", "1") + input("specular_ior", "float", "1.5") +
                          input("specular_roughness", "float", "0.5"),
                      {"specular_ior", "specular_roughness"});
  const uint32_t n = mxc::glsl::kTableSize;
  std::vector<double> mus;
  std::vector<glm::vec3> views;
  for (uint32_t i = 0; i < n; ++i) {
    const double mu = std::max(std::pow(double(i) / (n - 1.0), 2.0), 1e-4);
    mus.push_back(mu);
    views.push_back(glm::vec3(float(std::sqrt(1.0 - mu * mu)), 0.0f, float(mu)));
  }
  std::vector<WalkMeasurement> out;
  uint32_t seed = 40000;  // apart from the interface measurements' seeds
  for (uint32_t e = 0; e < mxc::glsl::kWalkEtaSteps; ++e) {
    const double eta = mxc::glsl::walkTableEta(int(e));
    for (uint32_t j = 0; j < n; ++j) {
      const double roughness = double(j) / (n - 1.0);
      furnace.set("specular_ior", {float(eta)});
      furnace.set("specular_roughness", {float(roughness)});
      std::vector<mxc::rt::Albedo> a = furnace.estimate(views, mxc::tools::kReflectanceSamples, seed++);
      for (size_t k = 0; k < views.size(); ++k) {
        out.push_back({"reflectance", eta, 0.0, roughness, mus[k], a[k].reflected.x, a[k].reflectedError.x});
      }
    }
    std::fprintf(stderr, "  reflectance eta %.3f measured\n", eta);
  }
  return out;
}

/// The walk's semi-infinite medium under the dielectric at normal incidence, three values of s
/// per estimate (one per colour channel: the flights are the same, mu_t = 1 on every channel).
std::vector<WalkMeasurement> measureMedia(mxc::rt::VulkanContext& context, const mxc::rt::AlbedoTables& tables) {
  // transmission_color e^-1 at depth 1: mu_t = 1; transmission_scatter = omega: mu_s = omega.
  WalkFurnace furnace(context, tables,
                      input("transmission_weight", "float", "1") + input("transmission_depth", "float", "1") +
                          input("transmission_color", "color3", "0.36787944, 0.36787944, 0.36787944") +
                          input("transmission_scatter", "color3", "0.5, 0.5, 0.5") +
                          input("transmission_scatter_anisotropy", "float", "0") + input("specular_ior", "float", "1.5") +
                          input("specular_roughness", "float", "0"),
                      {"transmission_scatter", "transmission_scatter_anisotropy", "specular_ior", "specular_roughness"});
  std::vector<WalkMeasurement> out;
  std::vector<double> ss;  // s = 1 (omega 0: E_spec) and the interior of (0, 1); s = 0 is C = 1 exactly
  for (int k = mxc::tools::kMediumSteps; k >= 1; --k) ss.push_back(double(k) / mxc::tools::kMediumSteps);
  uint32_t seed = 1;
  const auto start = std::chrono::steady_clock::now();
  for (uint32_t e = 0; e < mxc::glsl::kWalkEtaSteps; ++e) {
    const double eta = mxc::glsl::walkTableEta(int(e));
    for (uint32_t gi = 0; gi < mxc::glsl::kWalkAnisotropySteps; ++gi) {
      const double g = mxc::glsl::walkTableAnisotropy(int(gi));
      for (uint32_t r = 0; r < mxc::glsl::kWalkRoughnessSteps; ++r) {
        const double roughness = mxc::glsl::walkTableRoughness(int(r));
        furnace.set("transmission_scatter_anisotropy", {float(g)});
        furnace.set("specular_ior", {float(eta)});
        furnace.set("specular_roughness", {float(roughness)});
        for (size_t first = 0; first < ss.size(); first += 3) {
          std::array<float, 3> omega{};
          std::array<double, 3> s{};
          for (int c = 0; c < 3; ++c) {
            s[c] = ss[std::min(first + c, ss.size() - 1)];
            omega[c] = float((1.0 - s[c] * s[c]) / (1.0 - g * s[c] * s[c]));  // |g| < 1: > 0
          }
          furnace.set("transmission_scatter", {omega[0], omega[1], omega[2]});
          std::vector<mxc::rt::Albedo> a = furnace.estimate({glm::vec3(0.0f, 0.0f, 1.0f)}, mxc::tools::kMediumSamples,
                                                            seed++);
          for (int c = 0; c < 3 && first + c < ss.size(); ++c) {
            out.push_back({"medium", eta, g, roughness, s[c], a[0].reflected[c], a[0].reflectedError[c]});
          }
        }
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "  medium eta %.3f measured (%.0f s)\n", eta, seconds);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  const std::filesystem::path folder = argc > 2 ? argv[2] : "generated/tables";
  // measure: every kind; measure-KIND: that kind again, the others kept from the CSV.
  const std::vector<std::string> kinds = {"interface", "reflectance", "medium"};
  std::vector<std::string> measure;
  if (mode == "measure") {
    measure = kinds;
  } else if (mode.rfind("measure-", 0) == 0 &&
             std::find(kinds.begin(), kinds.end(), mode.substr(8)) != kinds.end()) {
    measure = {mode.substr(8)};
  } else if (mode != "fit") {
    std::fprintf(stderr, "usage: mxc-generate-walk-fits measure|measure-interface|measure-reflectance|measure-medium|fit [FOLDER]\n");
    return 2;
  }
  try {
    const std::filesystem::path csv = folder / "mxc_walk_measurements.csv";
    std::vector<WalkMeasurement> measurements;
    if (measure.size() != kinds.size()) {
      std::ifstream in(csv, std::ios::binary);
      if (!in) {
        std::fprintf(stderr, "error: cannot read %s\n", csv.c_str());
        return 1;
      }
      std::stringstream text;
      text << in.rdbuf();
      for (WalkMeasurement& m : mxc::tools::readMeasurements(text.str())) {
        if (std::find(measure.begin(), measure.end(), m.kind) == measure.end()) measurements.push_back(std::move(m));
      }
    }
    if (!measure.empty()) {
      mxc::rt::VulkanContext context;
      // The computed tables and no walk rows: the measurements' shaders read none (a translucent
      // base: no observed colour), and the committed walk rows may be of another layout.
      std::vector<float> texels = mxc::glsl::committedComputedTables().texels;
      texels.resize(size_t{mxc::glsl::kTableSize} * mxc::glsl::kTableHeight * 4, 0.0f);
      mxc::rt::AlbedoTables tables(context, std::move(texels));
      std::fprintf(stderr, "measuring the reference walk on %s...\n", context.deviceName().c_str());
      for (const std::string& kind : measure) {
        std::vector<WalkMeasurement> more = kind == "interface"     ? measureInterfaces(context, tables)
                                            : kind == "reflectance" ? measureReflectance(context, tables)
                                                                    : measureMedia(context, tables);
        measurements.insert(measurements.end(), more.begin(), more.end());
      }
      std::filesystem::create_directories(folder);
      if (std::optional<std::string> error = mxc::writeOutputFile(csv, mxc::tools::writeMeasurements(measurements))) {
        std::fprintf(stderr, "error: %s\n", error->c_str());
        return 3;
      }
      std::fprintf(stderr, "wrote %s\n", csv.c_str());
    }
    mxc::glsl::AlbedoTableData tables;
    tables.width = mxc::glsl::kTableSize;
    tables.height = mxc::glsl::kWalkTableRows;
    tables.texels = mxc::tools::walkTableRows(measurements);
    const std::filesystem::path out = folder / "mxc_walk_tables.bin";
    if (std::optional<std::string> error = mxc::writeOutputFile(out, mxc::glsl::encodeAlbedoTables(tables))) {
      std::fprintf(stderr, "error: %s\n", error->c_str());
      return 3;
    }
    std::fprintf(stderr, "wrote %s\n", out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
