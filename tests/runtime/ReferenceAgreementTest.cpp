// The reference tier against an independent implementation (issue 39, "Prove the reference
// independently"): the shader walk's furnace (compiler/glsl/library/mxc_walk.glsl, on the
// device, three channels per walk with weights) and the CPU walk (support/SlabReference.h,
// double precision, one channel per analog walk, written separately) agree on the reflected
// and the transmitted albedo of every channel at every view, within 4 of their combined
// standard errors, on materials that cover every layer kind: glossy-diffuse under a rough
// specular layer, a partial coloured coat, partial coloured fuzz, an F82 metal, rough clear
// glass, a coloured scattering translucent medium, coloured subsurface, a thin wall, emission
// under a coat, and all of them partially at once.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "support/MaterialSupport.h"
#include "support/SlabReference.h"

namespace mxc::test {
namespace {

std::string input(const char* name, const char* type, const std::string& value) {
  return fmt::format("    <input name=\"{}\" type=\"{}\" value=\"{}\" />\n", name, type, value);
}

struct Case {
  const char* name;
  std::string inputs;
};

std::vector<Case> cases() {
  return {
      {"glossy_diffuse", input("base_color", "color3", "0.7, 0.5, 0.3") + input("specular_roughness", "float", "0.5")},
      {"partial_coat", input("coat_weight", "float", "0.5") + input("coat_color", "color3", "0.8, 0.6, 0.9") +
                           input("coat_roughness", "float", "0.2") + input("coat_ior", "float", "1.6")},
      {"partial_fuzz", input("fuzz_weight", "float", "0.7") + input("fuzz_color", "color3", "0.9, 0.5, 0.4") +
                           input("fuzz_roughness", "float", "0.4") + input("base_color", "color3", "0.3, 0.6, 0.8")},
      {"metal", input("base_metalness", "float", "1") + input("base_color", "color3", "0.9, 0.6, 0.3") +
                    input("specular_color", "color3", "0.8, 0.9, 1") + input("specular_roughness", "float", "0.4")},
      {"rough_glass", input("transmission_weight", "float", "1") + input("specular_roughness", "float", "0.3")},
      // A base of weight 0: an absorber under the specular layer and a partial coat.
      {"black_base", input("base_weight", "float", "0") + input("coat_weight", "float", "0.5") +
                         input("specular_roughness", "float", "0.4")},
      // mu_t = -ln(colour) / depth = (0.105, 0.51, 1.2), mu_s = scatter / depth: omega (0.86, 0.78, 0.75).
      // (A white half-space, omega = 1, returns everything only after walks longer than either
      // walk's cap: the shader's loop budget loses a few percent there, README "Hard cases".)
      {"scattering_translucent", input("transmission_weight", "float", "1") + input("transmission_depth", "float", "1") +
                                     input("transmission_color", "color3", "0.9, 0.6, 0.3") +
                                     input("transmission_scatter", "color3", "0.09, 0.4, 0.9") +
                                     input("transmission_scatter_anisotropy", "float", "0.3") +
                                     input("specular_roughness", "float", "0.2")},
      {"subsurface", input("subsurface_weight", "float", "1") + input("subsurface_color", "color3", "0.8, 0.6, 0.4") +
                         input("subsurface_radius_scale", "color3", "1, 0.5, 0.25") +
                         input("subsurface_scatter_anisotropy", "float", "0.4") +
                         input("specular_roughness", "float", "0.3")},
      {"thin_wall", input("geometry_thin_walled", "boolean", "true") + input("transmission_weight", "float", "1") +
                        input("transmission_color", "color3", "0.7, 0.5, 0.3") + input("specular_roughness", "float", "0.2")},
      {"emission_under_coat", input("emission_luminance", "float", "10") + input("coat_weight", "float", "1") +
                                  input("coat_color", "color3", "0.7, 0.8, 0.9")},
      {"everything_partial", input("coat_weight", "float", "0.6") + input("fuzz_weight", "float", "0.4") +
                                 input("base_metalness", "float", "0.3") + input("subsurface_weight", "float", "0.5") +
                                 input("subsurface_color", "color3", "0.9, 0.7, 0.5") +
                                 input("transmission_weight", "float", "0.2") + input("base_color", "color3", "0.6, 0.4, 0.2")},
  };
}

class ReferenceAgreement : public ::testing::TestWithParam<Case> {};

TEST_P(ReferenceAgreement, ShaderWalkMatchesTheIndependentWalk) {
  const Case& c = GetParam();
  Context context;
  std::vector<ir::Material> materials = lowerText(context, openPbrDocument(c.inputs));
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  ASSERT_EQ(materials.size(), 1u);
  const ir::Material& m = materials.front();
  const double degrees[] = {0.0, 45.0, 75.0};
  std::vector<glm::vec3> views;
  for (double d : degrees) views.push_back(viewAt(d));
  const std::vector<rt::Albedo> shader = furnace(m, views, 1u << 15, {}, Accuracy::Reference);
  ASSERT_EQ(shader.size(), views.size());
  double worst = 0.0;
  for (int channel = 0; channel < 3; ++channel) {
    const slab::Stacks stacks = slab::stacksOf(m, channel);
    for (size_t v = 0; v < views.size(); ++v) {
      const slab::Albedo cpu = slab::albedo(stacks, glm::dvec3(views[v]), 1 << 15, 101u + 10u * v + channel);
      EXPECT_LT(cpu.cut, 1e-4);
      const struct {
        const char* what;
        double gpu, gpuError, cpu, cpuError;
      } parts[] = {{"reflected", shader[v].reflected[channel], shader[v].reflectedError[channel], cpu.reflected,
                    cpu.reflectedError},
                   {"transmitted", shader[v].transmitted[channel], shader[v].transmittedError[channel], cpu.transmitted,
                    cpu.transmittedError}};
      for (const auto& p : parts) {
        // 1e-6 keeps z finite where both are exactly 0 (nothing transmitted).
        const double z = (p.gpu - p.cpu) / std::sqrt(p.gpuError * p.gpuError + p.cpuError * p.cpuError + 1e-12);
        worst = std::max(worst, std::abs(z));
        EXPECT_LE(std::abs(z), 4.0) << c.name << ", channel " << channel << ", " << degrees[v] << " degrees, " << p.what
                                    << ": shader " << p.gpu << " +- " << p.gpuError << ", independent " << p.cpu
                                    << " +- " << p.cpuError << "\n" << slab::describe(stacks);
      }
    }
  }
  std::printf("%s: largest |z| %.2f over 3 channels x 3 views x reflected and transmitted\n", c.name, worst);
}

std::string caseName(const ::testing::TestParamInfo<Case>& c) { return c.param.name; }

INSTANTIATE_TEST_SUITE_P(Materials, ReferenceAgreement, ::testing::ValuesIn(cases()), caseName);

}  // namespace
}  // namespace mxc::test
