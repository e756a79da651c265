// The reference tier on its own (issue 13, "The reference is tested on its own"): its random
// walk through the slab stacks (compiler/glsl/library/mxc_walk.glsl) against closed forms that
// do not come from the walk (tests/support/ClosedForms.h; ../shared/reference/physics-notes.md),
// its eval estimate against its own sampling, and its reciprocity.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "support/ClosedForms.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

constexpr Accuracy kReference = Accuracy::Reference;

ir::Material openPbr(Context& context, const std::string& inputs) {
  std::vector<ir::Material> materials = lowerText(context, openPbrDocument(inputs));
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(materials.size(), 1u);
  return materials.empty() ? ir::Material{} : std::move(materials.front());
}

std::string input(const char* name, const char* type, const std::string& value) {
  return fmt::format("    <input name=\"{}\" type=\"{}\" value=\"{}\" />\n", name, type, value);
}

/// |value - expected| within 4 standard errors plus an absolute slack.
void expectNear(double value, double expected, double error, double slack, const std::string& what) {
  EXPECT_NEAR(value, expected, 4.0 * error + slack) << what << " (standard error " << error << ")";
}

// Physics notes 2.1: a rough conductor with F = 1 reflects everything, whatever its roughness,
// once every order of scattering on the microsurface is counted (Heitz et al. 2016).
TEST(ReferenceWalk, WhiteConductorIsOneAtEveryRoughness) {
  for (const char* roughness : {"0.2", "0.6", "1"}) {
    Context context;
    ir::Material m = openPbr(context, input("base_metalness", "float", "1") + input("base_color", "color3", "1, 1, 1") +
                                          input("specular_color", "color3", "1, 1, 1") +
                                          input("specular_roughness", "float", roughness));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0), viewAt(45), viewAt(80)}, 4096, {}, kReference);
    ASSERT_EQ(albedo.size(), 3u);
    for (const rt::Albedo& a : albedo) expectNear(a.total().x, 1.0, a.reflectedError.x, 1e-4, roughness);
  }
}

// Physics notes 2.1: a rough dielectric without absorption reflects and transmits everything.
TEST(ReferenceWalk, RoughDielectricConservesEnergy) {
  for (const char* roughness : {"0.3", "0.8"}) {
    Context context;
    ir::Material m = openPbr(context, input("transmission_weight", "float", "1") +
                                          input("specular_roughness", "float", roughness));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0), viewAt(50), viewAt(80)}, 4096, {}, kReference);
    ASSERT_EQ(albedo.size(), 3u);
    for (const rt::Albedo& a : albedo) {
      expectNear(a.total().x, 1.0, a.reflectedError.x + a.transmittedError.x, 1e-4, roughness);
      EXPECT_GT(a.transmitted.x, 0.5f) << roughness;
    }
  }
}

// Physics notes 2.3: a smooth dielectric reflects the Fresnel factor at every angle.
TEST(ReferenceWalk, SmoothDielectricReflectsFresnel) {
  Context context;
  ir::Material m = openPbr(context, input("transmission_weight", "float", "1") + input("specular_roughness", "float", "0") +
                                        input("specular_ior", "float", "1.5"));
  const double degrees[] = {0, 30, 60, 80};
  std::vector<glm::vec3> views;
  for (double d : degrees) views.push_back(viewAt(d));
  std::vector<rt::Albedo> albedo = furnace(m, views, 16384, {}, kReference);
  ASSERT_EQ(albedo.size(), views.size());
  for (size_t k = 0; k < views.size(); ++k) {
    const double mu = std::cos(degrees[k] * 3.14159265358979 / 180.0);
    expectNear(albedo[k].reflected.x, closed::fresnel(mu, 1.5), albedo[k].reflectedError.x, 1e-3,
               fmt::format("R at {} degrees", degrees[k]));
  }
}

// Physics notes 2.9: a Lambertian base under a smooth dielectric of IOR 1.5 (a coat, with the
// specular interface index-matched to it) reflects the interfaced-Lambertian albedo.
TEST(ReferenceWalk, LambertianUnderSmoothCoatMatchesClosedForm) {
  for (double rho : {0.5, 0.8}) {
    Context context;
    const std::string c = fmt::format("{0}, {0}, {0}", rho);
    ir::Material m = openPbr(context, input("coat_weight", "float", "1") + input("coat_ior", "float", "1.5") +
                                          input("coat_roughness", "float", "0") + input("specular_ior", "float", "1.5") +
                                          input("specular_roughness", "float", "0") + input("base_color", "color3", c));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0), viewAt(45)}, 16384, {}, kReference);
    ASSERT_EQ(albedo.size(), 2u);
    expectNear(albedo[0].total().x, closed::interfacedLambertian(1.0, rho, 1.5), albedo[0].reflectedError.x, 2e-3,
               fmt::format("rho {} at normal incidence", rho));
    expectNear(albedo[1].total().x, closed::interfacedLambertian(std::sqrt(0.5), rho, 1.5), albedo[1].reflectedError.x,
               2e-3, fmt::format("rho {} at 45 degrees", rho));
  }
  // The anchor of the notes: 0.316 at rho 0.5 and normal incidence.
  EXPECT_NEAR(closed::interfacedLambertian(1.0, 0.5, 1.5), 0.316, 1e-3);
}

// OpenPBR "Glossy-diffuse", eq. glossy_diffuse_albedo_constraint: base_color C is what comes
// back of the light the gloss lets in, for a Lambertian base: at normal incidence under a
// smooth gloss the albedo is F0 + (1 - F0) C, although the walk traps light under the gloss.
TEST(ReferenceWalk, GlossyDiffuseObservedColourIsBaseColor) {
  for (double color : {0.3, 0.8}) {
    Context context;
    ir::Material m = openPbr(context, input("specular_roughness", "float", "0") +
                                          input("base_color", "color3", fmt::format("{0}, {0}, {0}", color)));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0)}, 16384, {}, kReference);
    ASSERT_EQ(albedo.size(), 1u);
    const double f0 = 0.04;  // ((1.5 - 1) / (1.5 + 1))^2
    expectNear(albedo[0].total().x, f0 + (1.0 - f0) * color, albedo[0].reflectedError.x, 2e-3,
               fmt::format("base_color {}", color));
  }
}

/// The constant components of a medium's slot in a lowered material.
std::vector<float> mediumSlot(const ir::Material& m, ir::Slot slot) {
  if (m.media.empty()) return {};
  const ir::Param* p = m.media.front().slots.find(slot);
  return p && p->present() ? m.exprs.constantComponents(p->value) : std::vector<float>{};
}

// Physics notes 2.9: a semi-infinite, isotropically scattering medium without an interface
// (OpenPBR subsurface under an IOR of 1, which no light sees) has the albedo
// 1 - H(mu) sqrt(1 - omega), Chandrasekhar's H computed by iterating its integral equation.
TEST(ReferenceWalk, SemiInfiniteMediumMatchesChandrasekhar) {
  Context context;
  ir::Material m = openPbr(context, input("subsurface_weight", "float", "1") + input("specular_ior", "float", "1") +
                                        input("subsurface_color", "color3", "0.5, 0.5, 0.5") +
                                        input("subsurface_radius_scale", "color3", "1, 1, 1"));
  const std::vector<float> absorption = mediumSlot(m, ir::Slot::Absorption);
  const std::vector<float> scattering = mediumSlot(m, ir::Slot::Scattering);
  ASSERT_EQ(absorption.size(), 3u);
  ASSERT_EQ(scattering.size(), 3u);
  const double omega = scattering[0] / double(scattering[0] + absorption[0]);
  const double degrees[] = {0, 60};
  std::vector<rt::Albedo> albedo = furnace(m, {viewAt(degrees[0]), viewAt(degrees[1])}, 8192, {}, kReference);
  ASSERT_EQ(albedo.size(), 2u);
  for (size_t k = 0; k < 2; ++k) {
    const double mu = std::cos(degrees[k] * 3.14159265358979 / 180.0);
    expectNear(albedo[k].total().x, closed::semiInfiniteAlbedo(omega, mu), albedo[k].reflectedError.x, 3e-3,
               fmt::format("omega {} at {} degrees", omega, degrees[k]));
  }
}

// Beer-Lambert along the refracted path: an absorbing coat (optical depth tau at normal
// incidence) under a smooth interface over a perfect mirror reflects
// F + (1 - F)^2 T^2 / (1 - F T^2), T = exp(-tau / mu_t) one way along the refracted cosine mu_t,
// and F the same inside as outside (Stokes relations).
TEST(ReferenceWalk, AbsorbingCoatFollowsBeerLambertAlongTheRefractedPath) {
  Context context;
  ir::Material m = openPbr(context, input("coat_weight", "float", "1") + input("coat_color", "color3", "0.5, 0.5, 0.5") +
                                        input("coat_ior", "float", "1.5") + input("base_metalness", "float", "1") +
                                        input("base_color", "color3", "1, 1, 1") + input("specular_color", "color3", "1, 1, 1") +
                                        input("specular_roughness", "float", "0"));
  const std::vector<float> absorption = mediumSlot(m, ir::Slot::Absorption);
  ASSERT_EQ(absorption.size(), 3u);
  const std::vector<float> thickness = mediumSlot(m, ir::Slot::Thickness);
  const double tau = absorption[0] * (thickness.empty() ? 1.0 : thickness[0]);
  const double degrees[] = {0, 45, 70};
  std::vector<glm::vec3> views;
  for (double d : degrees) views.push_back(viewAt(d));
  std::vector<rt::Albedo> albedo = furnace(m, views, 8192, {}, kReference);
  ASSERT_EQ(albedo.size(), views.size());
  for (size_t k = 0; k < views.size(); ++k) {
    const double mu = std::cos(degrees[k] * 3.14159265358979 / 180.0);
    const double mut = std::sqrt(1.0 - (1.0 - mu * mu) / (1.5 * 1.5));
    const double f = closed::fresnel(mu, 1.5), t = std::exp(-tau / mut);
    const double expected = f + (1.0 - f) * (1.0 - f) * t * t / (1.0 - f * t * t);
    expectNear(albedo[k].total().x, expected, albedo[k].reflectedError.x, 2e-3, fmt::format("{} degrees", degrees[k]));
  }
}

// Convergence: the reference is an unbiased Monte Carlo estimate, so its error falls as
// N^-1/2. The root-mean-square error of the furnace over 48 seeds at N = 64 to 4096 samples,
// against the exact value (the interfaced Lambertian above, the limit of any longer run),
// fitted on log-log axes, has slope -0.5 within 0.05. The seeds are fixed: the test is
// deterministic on a device.
TEST(ReferenceWalk, ErrorFallsAsOneOverSqrtN) {
  Context context;
  ir::Material m = openPbr(context, input("coat_weight", "float", "1") + input("coat_ior", "float", "1.5") +
                                        input("coat_roughness", "float", "0") + input("specular_ior", "float", "1.5") +
                                        input("specular_roughness", "float", "0") + input("base_color", "color3", "0.5, 0.5, 0.5"));
  Prepared p = prepare(m, glsl::ShaderKind::Furnace, {}, kReference);
  ASSERT_TRUE(p.ok());
  rt::FurnaceEstimator estimator(Device::get().context, Device::get().tables, *p.resources, p.shader.interface, p.words);
  const double exact = closed::interfacedLambertian(1.0, 0.5, 1.5);
  const uint32_t counts[] = {64, 256, 1024, 4096};
  constexpr int kSeeds = 48;
  std::vector<double> x, y;
  for (uint32_t n : counts) {
    double squares = 0.0;
    for (int seed = 0; seed < kSeeds; ++seed) {
      std::vector<rt::Albedo> a = estimator.estimate({viewAt(0)}, n, 1000u * n + static_cast<uint32_t>(seed));
      ASSERT_EQ(a.size(), 1u);
      squares += (a[0].total().x - exact) * (a[0].total().x - exact);
    }
    x.push_back(std::log(double(n)));
    y.push_back(0.5 * std::log(squares / kSeeds));
  }
  // Least-squares slope of y over x.
  const double mx = (x[0] + x[1] + x[2] + x[3]) / 4.0, my = (y[0] + y[1] + y[2] + y[3]) / 4.0;
  double sxy = 0.0, sxx = 0.0;
  for (size_t k = 0; k < x.size(); ++k) {
    sxy += (x[k] - mx) * (y[k] - my);
    sxx += (x[k] - mx) * (x[k] - mx);
  }
  const double slope = sxy / sxx;  // sxx > 0: four distinct counts
  std::printf("convergence: RMS error %.5f %.5f %.5f %.5f at N = 64, 256, 1024, 4096; slope %.3f\n", std::exp(y[0]),
              std::exp(y[1]), std::exp(y[2]), std::exp(y[3]), slope);
  EXPECT_NEAR(slope, -0.5, 0.05) << "RMS errors " << std::exp(y[0]) << ", " << std::exp(y[1]) << ", " << std::exp(y[2])
                                 << ", " << std::exp(y[3]);
}

// An emission layer emits; it neither absorbs nor reflects (OpenPBR "Emission": the emission
// sits under the coat and fuzz, on the base): the albedo with and without it is the same.
TEST(ReferenceWalk, EmissionLeavesTheAlbedoAlone) {
  double albedo[2] = {0.0, 0.0}, error[2] = {0.0, 0.0};
  for (int k = 0; k < 2; ++k) {
    Context context;
    ir::Material m = openPbr(context, input("emission_luminance", "float", k == 0 ? "0" : "100"));
    std::vector<rt::Albedo> a = furnace(m, {viewAt(30)}, 8192, {}, kReference);
    ASSERT_EQ(a.size(), 1u);
    albedo[k] = a[0].total().x;
    error[k] = a[0].reflectedError.x;
  }
  EXPECT_GT(albedo[0], 0.7);
  expectNear(albedo[1], albedo[0], error[0] + error[1], 1e-3, "with emission");
}

/// Stratified directions on the upper hemisphere, each standing for 2 pi / count of solid angle.
std::vector<glm::vec3> hemisphere(int side) {
  std::vector<glm::vec3> out;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const double z = (i + 0.5) / side, phi = 2.0 * 3.14159265358979 * (j + 0.5) / side;
      const double r = std::sqrt(1.0 - z * z);
      out.push_back(glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
    }
  }
  return out;
}

// eval's next-event estimate and the walk's own sampling describe one BSDF: the integral of
// eval's f cos over the hemisphere is the furnace's albedo (a rough coat over a rough specular
// layer over a diffuse base: connections through two rough interfaces and their chains).
TEST(ReferenceWalk, EvalIntegratesToTheSampledAlbedo) {
  Context context;
  ir::Material m = openPbr(context, input("coat_weight", "float", "1") + input("coat_roughness", "float", "0.4") +
                                        input("specular_roughness", "float", "0.5"));
  const glm::vec3 wo = viewAt(30);
  const std::vector<glm::vec3> dirs = hemisphere(48);
  std::vector<rt::DirectionPair> pairs;
  for (const glm::vec3& wi : dirs) pairs.push_back({wo, wi});
  std::vector<glm::vec4> f = evaluate(m, pairs, kReference, 32);
  ASSERT_EQ(f.size(), pairs.size());
  double integral = 0.0;
  for (const glm::vec4& v : f) integral += v.x * 2.0 * 3.14159265358979 / double(dirs.size());
  std::vector<rt::Albedo> albedo = furnace(m, {wo}, 16384, {}, kReference);
  ASSERT_EQ(albedo.size(), 1u);
  // 2%: the quadrature of the glossy peaks on a 48 x 48 grid and the estimate's own noise.
  EXPECT_NEAR(integral, albedo[0].reflected.x, 0.02) << "eval integrates to " << integral;
}

// Reflection off a layered dielectric over a diffuse base is reciprocal (the model is: every
// interface and the base are), so the estimates of f cos / |cos wi| agree when wo and wi swap.
TEST(ReferenceWalk, ReflectionIsReciprocal) {
  Context context;
  ir::Material m = openPbr(context, input("specular_roughness", "float", "0.4") + input("base_color", "color3", "0.6, 0.6, 0.6"));
  const glm::vec3 a = viewAt(20), b = glm::normalize(glm::vec3(-0.5f, 0.3f, 0.6f)), c = viewAt(70);
  const std::vector<rt::DirectionPair> pairs = {{a, b}, {b, a}, {a, c}, {c, a}};
  std::vector<glm::vec4> f = evaluate(m, pairs, kReference, 512);
  ASSERT_EQ(f.size(), pairs.size());
  for (size_t k = 0; k < pairs.size(); k += 2) {
    const double forward = f[k].x / pairs[k].wi.z, backward = f[k + 1].x / pairs[k + 1].wi.z;
    EXPECT_GT(forward, 0.0);
    // 5%: 512 walks per estimate leave a relative noise of about 1.5%.
    EXPECT_NEAR(forward / backward, 1.0, 0.05) << "pair " << k / 2 << ": " << forward << " vs " << backward;
  }
  EXPECT_TRUE(Device::get().context.validationMessages().empty());
}

}  // namespace
}  // namespace mxc::test
