// Physical checks through the compute path (runtime/Evaluator): directional albedos from the
// white furnace and f cos values against the closed forms and computed anchors of
// ../shared/reference/physics-notes.md (section numbers below refer to it).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "support/ClosedForms.h"
#include "support/MaterialSupport.h"
#include "support/MicrosurfaceWalk.h"

namespace mxc::test {
namespace {

/// |value - expected| within k standard errors plus an absolute slack (for float sums).
void expectNear(float value, float expected, float error, float slack, const std::string& what) {
  EXPECT_NEAR(value, expected, 4.0f * error + slack) << what << " (standard error " << error << ")";
}

ir::Material single(Context& context, const std::string& text, const lower::LoweringOptions& options = {}) {
  std::vector<ir::Material> materials = lowerText(context, text, options);
  EXPECT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  EXPECT_EQ(materials.size(), 1u);
  return materials.empty() ? ir::Material{} : std::move(materials.front());
}

// 2.1: Lambert, E = rho exactly.
TEST(Furnace, WhiteLambertianReturnsAlbedoOne) {
  Context context;
  ir::Material m = single(context, bsdfDocument("  <oren_nayar_diffuse_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                "    <input name=\"color\" type=\"color3\" value=\"1, 1, 1\" />\n"
                                                "  </oren_nayar_diffuse_bsdf>\n"));
  std::vector<glm::vec3> views{viewAt(0), viewAt(30), viewAt(60), viewAt(85)};
  std::vector<rt::Albedo> albedo = furnace(m, views, 16384);
  ASSERT_EQ(albedo.size(), views.size());
  for (size_t k = 0; k < views.size(); ++k) {
    for (int c = 0; c < 3; ++c) expectNear(albedo[k].total()[c], 1.0f, albedo[k].reflectedError[c], 1e-4f, "E");
    EXPECT_EQ(albedo[k].transmitted, glm::vec3(0.0f));
  }
  EXPECT_TRUE(Device::get().context.validationMessages().empty());
}

// 2.1: EON with rho = 1 has E = 1 for every roughness and view (OpenPBR "Glossy-diffuse").
TEST(Furnace, WhiteEonIsOneAtAnyRoughness) {
  for (const char* roughness : {"0.5", "1"}) {
    Context context;
    ir::Material m = single(context, openPbrDocument(fmt::format("    <input name=\"base_color\" type=\"color3\" value=\"1, 1, 1\" />\n"
                                                         "    <input name=\"specular_weight\" type=\"float\" value=\"0\" />\n"
                                                         "    <input name=\"base_diffuse_roughness\" type=\"float\" value=\"{}\" />\n",
                                                         roughness)));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0), viewAt(45), viewAt(75)}, 65536);
    // The EON compensation is exact: what is left is Monte Carlo error and float sums.
    for (const rt::Albedo& a : albedo) expectNear(a.total().x, 1.0f, a.reflectedError.x, 5e-4f, roughness);
  }
}

// 2.3: a smooth dielectric reflects F0 = ((n - 1) / (n + 1))^2 at normal incidence.
TEST(Furnace, SmoothDielectricNormalReflectanceIsF0) {
  for (double n : {1.33, 1.5, 2.0}) {
    const double f0 = std::pow((n - 1.0) / (n + 1.0), 2.0);
    for (const char* mode : {"R", "RT"}) {
      Context context;
      ir::Material m = single(context, bsdfDocument(fmt::format("  <dielectric_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                                "    <input name=\"ior\" type=\"float\" value=\"{}\" />\n"
                                                                "    <input name=\"scatter_mode\" type=\"string\" value=\"{}\" />\n"
                                                                "    <input name=\"roughness\" type=\"vector2\" value=\"0, 0\" />\n"
                                                                "  </dielectric_bsdf>\n",
                                                                n, mode)));
      std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0)}, 65536);
      ASSERT_EQ(albedo.size(), 1u);
      const std::string what = fmt::format("n = {}, scatter_mode {}", n, mode);
      // R alone is exact (the delta lobe is sampled with probability 1); with T the choice of
      // reflection is random, so the estimate has a Monte Carlo error.
      expectNear(albedo[0].reflected.x, float(f0), albedo[0].reflectedError.x, 1e-5f, what);
      if (std::string(mode) == "RT") expectNear(albedo[0].total().x, 1.0f, albedo[0].transmittedError.x, 1e-5f, what);
    }
  }
}

// 2.3: specular_weight xi scales F0 exactly (OpenPBR eq. modulated_ior): IOR 1.5, xi = 0.5 gives 0.02.
TEST(Furnace, SpecularWeightScalesF0) {
  Context context;
  ir::Material m = single(context, openPbrDocument("    <input name=\"base_color\" type=\"color3\" value=\"0, 0, 0\" />\n"
                                           "    <input name=\"specular_weight\" type=\"float\" value=\"0.5\" />\n"
                                           "    <input name=\"specular_roughness\" type=\"float\" value=\"0\" />\n"));
  std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0)}, 16384);
  ASSERT_EQ(albedo.size(), 1u);
  expectNear(albedo[0].reflected.y, 0.02f, albedo[0].reflectedError.y, 1e-5f, "F0'");
}

// OpenPBR "Darkening": a Lambertian base (albedo 0.5, no base specular) under a smooth clear
// coat of IOR 1.5, seen at normal incidence. The coat reflects F = 0.04; the base gets
// (1 - F) E_b Delta with Delta = (1 - K) / (1 - E_b K) and K = K_r = 1 - (1 - E_F) / 1.5^2 =
// 0.59633 (E_F = 0.091776, the hemispherical Fresnel average; r_b = 1 for a base without
// specular). So E_c = 0.04 + 0.48 * 0.57515 = 0.31607 (eq. interfaced_lambertian_albedo).
// coat_darkening 0 boosts the base back: E_c = 0.04 + 0.48 = 0.52 (eq. undarkened_coat_albedo).
TEST(Furnace, CoatDarkeningFollowsTheInterfacedLambertian) {
  for (const auto& [darkening, expected] : {std::pair{1.0f, 0.31607f}, std::pair{0.0f, 0.52f}}) {
    Context context;
    ir::Material m = single(
        context, openPbrDocument(fmt::format("    <input name=\"base_color\" type=\"color3\" value=\"0.5, 0.5, 0.5\" />\n"
                                     "    <input name=\"specular_weight\" type=\"float\" value=\"0\" />\n"
                                     "    <input name=\"coat_weight\" type=\"float\" value=\"1\" />\n"
                                     "    <input name=\"coat_roughness\" type=\"float\" value=\"0\" />\n"
                                     "    <input name=\"coat_ior\" type=\"float\" value=\"1.5\" />\n"
                                     "    <input name=\"coat_darkening\" type=\"float\" value=\"{}\" />\n",
                                     darkening)));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0)}, 262144);
    ASSERT_EQ(albedo.size(), 1u);
    // Slack: the 16-point Fresnel average (3e-4 in E_F) and the tabulated coat albedo.
    expectNear(albedo[0].total().y, expected, albedo[0].reflectedError.y, 2e-3f,
               fmt::format("coat_darkening {}", darkening));
    if (darkening == 1.0f) {
      // At every view, against the interfaced Lambertian computed by its own quadrature
      // (support/ClosedForms.h): with K = K_r the darkening is exact for this configuration.
      const double degrees[] = {30.0, 60.0, 75.0};
      std::vector<rt::Albedo> more = furnace(m, {viewAt(30), viewAt(60), viewAt(75)}, 262144);
      ASSERT_EQ(more.size(), 3u);
      for (size_t k = 0; k < 3; ++k) {
        const double mu = std::cos(degrees[k] * 3.14159265358979 / 180.0);
        expectNear(more[k].total().y, static_cast<float>(closed::interfacedLambertian(mu, 0.5, 1.5)),
                   more[k].reflectedError.y, 2e-3f, fmt::format("interfaced Lambertian at {} degrees", degrees[k]));
      }
    }
  }
}

// 2.6: thin film on a smooth dielectric (air / film 1.4 / base 1.5), at normal incidence.
TEST(Furnace, ThinFilmMatchesAiryAnchors) {
  struct Case {
    const char* thickness;
    glm::vec3 expected;
  };
  for (const Case& c : {Case{"0.0001", glm::vec3(0.04f)}, Case{"10", {0.0396f, 0.0394f, 0.0392f}},
                        Case{"100", {0.0179f, 0.0180f, 0.0209f}}, Case{"10000", glm::vec3(0.0289f)}}) {
    Context context;
    ir::Material m = single(context, bsdfDocument(fmt::format("  <dielectric_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                              "    <input name=\"ior\" type=\"float\" value=\"1.5\" />\n"
                                                              "    <input name=\"thinfilm_thickness\" type=\"float\" value=\"{}\" />\n"
                                                              "    <input name=\"thinfilm_ior\" type=\"float\" value=\"1.4\" />\n"
                                                              "  </dielectric_bsdf>\n",
                                                              c.thickness)));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(0)}, 64);
    ASSERT_EQ(albedo.size(), 1u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(albedo[0].reflected[k], c.expected[k], 1e-4f) << "thickness " << c.thickness << " nm, channel " << k;
    }
  }
}

// 2.2: single-scattering GGX albedo with F = 1 (computed table; E(1) = 1 - ln 2 at alpha = 1):
// the fast tier has no multiple-scattering compensation.
TEST(Furnace, GgxAlbedoMatchesComputedTable) {
  struct Case {
    const char* alpha;
    double degrees;
    float expected;
  };
  for (const Case& c : {Case{"0.25", 0, 0.916f}, Case{"0.25", 60, 0.857f}, Case{"0.5625", 0, 0.627f},
                        Case{"0.5625", 60, 0.663f}, Case{"1", 0, 0.30685f}, Case{"1", 60, 0.451f}}) {
    Context context;
    ir::Material m = single(context, bsdfDocument(fmt::format("  <generalized_schlick_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                              "    <input name=\"color0\" type=\"color3\" value=\"1, 1, 1\" />\n"
                                                              "    <input name=\"roughness\" type=\"vector2\" value=\"{0}, {0}\" />\n"
                                                              "  </generalized_schlick_bsdf>\n",
                                                              c.alpha)));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(c.degrees)}, 262144, {}, Accuracy::Fast);
    ASSERT_EQ(albedo.size(), 1u);
    // The table is given to 3 digits.
    expectNear(albedo[0].reflected.x, c.expected, albedo[0].reflectedError.x, 1.5e-3f,
               fmt::format("alpha {} at {} degrees", c.alpha, c.degrees));
  }
}

// 2.2: a rough dielectric (eta 1.5), single scattering, R + T with separable Smith for the
// refraction, as the fast tier has it.
TEST(Furnace, RoughDielectricMatchesComputedAlbedo) {
  struct Case {
    const char* alpha;
    double degrees;
    float expected;
  };
  for (const Case& c : {Case{"1", 0, 0.894f}, Case{"1", 60, 0.672f}, Case{"0.25", 0, 0.992f}, Case{"0.25", 60, 0.960f}}) {
    Context context;
    ir::Material m = single(context, bsdfDocument(fmt::format("  <dielectric_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                              "    <input name=\"ior\" type=\"float\" value=\"1.5\" />\n"
                                                              "    <input name=\"scatter_mode\" type=\"string\" value=\"RT\" />\n"
                                                              "    <input name=\"roughness\" type=\"vector2\" value=\"{0}, {0}\" />\n"
                                                              "  </dielectric_bsdf>\n",
                                                              c.alpha)));
    std::vector<rt::Albedo> albedo = furnace(m, {viewAt(c.degrees)}, 262144, {}, Accuracy::Fast);
    ASSERT_EQ(albedo.size(), 1u);
    // The notes' reflection uses separable Smith too; ours is height-correlated (about 0.003 more).
    expectNear(albedo[0].total().x, c.expected, albedo[0].reflectedError.x + albedo[0].transmittedError.x, 5e-3f,
               fmt::format("alpha {} at {} degrees", c.alpha, c.degrees));
  }
}

/// Views from normal incidence to 80 degrees in steps of 10.
std::vector<glm::vec3> viewsTo80() {
  std::vector<glm::vec3> views;
  for (int d = 0; d <= 80; d += 10) views.push_back(viewAt(d));
  return views;
}

/// Every view's total albedo (channel y) within `tolerance` of 1, beyond the estimate's own
/// Monte Carlo error (3 standard errors).
void expectLossless(const std::vector<rt::Albedo>& albedo, float tolerance, const std::string& what) {
  ASSERT_EQ(albedo.size(), 9u) << what;
  for (size_t k = 0; k < albedo.size(); ++k) {
    const float error = albedo[k].reflectedError.y + albedo[k].transmittedError.y;
    EXPECT_NEAR(albedo[k].total().y, 1.0f, tolerance + 3.0f * error)
        << what << " at " << 10 * k << " degrees (standard error " << error << ")";
  }
}

// 2.1 with 2.2's compensation (issue 13's acceptance): on the balanced tier a white conductor
// (F = 1) has albedo 1 at every roughness and view from 0 to 80 degrees, within 0.01; the fast
// tier, without compensation, keeps single scattering's loss (1 - ln 2 at roughness 1, normal
// incidence).
TEST(Furnace, WhiteConductorIsLosslessOnBalanced) {
  for (const char* roughness : {"0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1"}) {
    for (const char* model : {"openpbr", "schlick"}) {
      Context context;
      const std::string text =
          std::string(model) == "openpbr"
              ? openPbrDocument(fmt::format("    <input name=\"base_metalness\" type=\"float\" value=\"1\" />\n"
                                            "    <input name=\"base_color\" type=\"color3\" value=\"1, 1, 1\" />\n"
                                            "    <input name=\"specular_roughness\" type=\"float\" value=\"{}\" />\n",
                                            roughness))
              : bsdfDocument(fmt::format("  <generalized_schlick_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                         "    <input name=\"color0\" type=\"color3\" value=\"1, 1, 1\" />\n"
                                         "    <input name=\"roughness\" type=\"vector2\" value=\"{0}, {0}\" />\n"
                                         "  </generalized_schlick_bsdf>\n",
                                         std::stof(roughness) * std::stof(roughness)));
      ir::Material m = single(context, text);
      expectLossless(furnace(m, viewsTo80(), 262144), 0.01f, fmt::format("{} roughness {}", model, roughness));
    }
  }
  Context context;
  ir::Material m = single(context, openPbrDocument("    <input name=\"base_metalness\" type=\"float\" value=\"1\" />\n"
                                                   "    <input name=\"base_color\" type=\"color3\" value=\"1, 1, 1\" />\n"
                                                   "    <input name=\"specular_roughness\" type=\"float\" value=\"1\" />\n"));
  std::vector<rt::Albedo> fast = furnace(m, {viewAt(0)}, 65536, {}, Accuracy::Fast);
  ASSERT_EQ(fast.size(), 1u);
  expectNear(fast[0].total().y, 0.30685f, fast[0].reflectedError.y, 2e-3f, "fast tier, roughness 1");
}

// OpenPBR "Metal": specular_color is the F82 edge tint, and OpenPBR's own metal presets set it
// above 1 (rubidium: 1.028, 1.041, 1.096). It is used as given: near grazing the blue reflectance
// of rubidium rises by about 0.08 over an untinted edge; and F-82 keeps the reflectance at or
// under 1, so even a tint of 2 on a white metal gains no energy at any angle.
TEST(Furnace, MetalEdgeTintAboveOneIsUsedWithoutEnergyGain) {
  auto metal = [](const std::string& base, const std::string& tint) {
    return openPbrDocument(fmt::format("    <input name=\"base_metalness\" type=\"float\" value=\"1\" />\n"
                                       "    <input name=\"base_color\" type=\"color3\" value=\"{}\" />\n"
                                       "    <input name=\"specular_color\" type=\"color3\" value=\"{}\" />\n"
                                       "    <input name=\"specular_roughness\" type=\"float\" value=\"0\" />\n",
                                       base, tint));
  };
  Context tinted, untinted;
  ir::Material a = single(tinted, metal("0.892, 0.862, 0.764", "1.028, 1.041, 1.096"));
  ir::Material b = single(untinted, metal("0.892, 0.862, 0.764", "1, 1, 1"));
  const std::vector<rt::Albedo> ta = furnace(a, {viewAt(81.8f)}, 4096);  // cos = 1/7, F82's angle
  const std::vector<rt::Albedo> tb = furnace(b, {viewAt(81.8f)}, 4096);
  ASSERT_EQ(ta.size(), 1u);
  ASSERT_EQ(tb.size(), 1u);
  EXPECT_GT(ta[0].total().z - tb[0].total().z, 0.05f) << "the blue edge tint 1.096 is applied, not clamped to 1";
  EXPECT_LE(ta[0].total().z, 1.0f + 1e-3f);
  Context white;
  ir::Material w = single(white, metal("1, 1, 1", "2, 2, 2"));
  for (const rt::Albedo& x : furnace(w, viewsTo80(), 4096)) {
    EXPECT_LE(std::max({x.total().x, x.total().y, x.total().z}), 1.0f + 1e-3f) << "white metal, edge tint 2";
  }
}

// 2.1: the default OpenPBR dielectric over a white base at every roughness, 0 to 80 degrees,
// within 0.01 of 1 on the balanced tier (issue 13's acceptance), and never above 1 on either tier.
TEST(Furnace, OpenPbrWhiteBaseConservesEnergy) {
  for (const char* roughness : {"0", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1"}) {
    Context context;
    ir::Material m = single(context, openPbrDocument(fmt::format("    <input name=\"base_color\" type=\"color3\" value=\"1, 1, 1\" />\n"
                                                         "    <input name=\"specular_roughness\" type=\"float\" value=\"{}\" />\n",
                                                         roughness)));
    expectLossless(furnace(m, viewsTo80(), 65536), 0.01f, fmt::format("specular_roughness {}", roughness));
    for (const rt::Albedo& a : furnace(m, viewsTo80(), 65536, {}, Accuracy::Fast)) {
      EXPECT_LE(a.total().y, 1.0f + 4.0f * a.reflectedError.y + 2e-3f) << "fast, specular_roughness " << roughness;
    }
  }
}

// 2.2's "an energy-preserving dielectric must give 1 once compensated": a rough non-absorbing
// dielectric reflects and transmits all it receives on the balanced tier, seen from the denser
// side too (IOR 1 / 1.5: total internal reflection included).
TEST(Furnace, RoughDielectricIsLosslessOnBalanced) {
  for (const char* ior : {"1.5", "1.33", "0.6667"}) {
    for (const char* alpha : {"0.04", "0.25", "0.5", "1"}) {
      Context context;
      ir::Material m = single(context, bsdfDocument(fmt::format("  <dielectric_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                                "    <input name=\"ior\" type=\"float\" value=\"{}\" />\n"
                                                                "    <input name=\"scatter_mode\" type=\"string\" value=\"RT\" />\n"
                                                                "    <input name=\"roughness\" type=\"vector2\" value=\"{}, {}\" />\n"
                                                                "  </dielectric_bsdf>\n",
                                                                ior, alpha, alpha)));
      expectLossless(furnace(m, viewsTo80(), 262144), 0.01f, fmt::format("ior {} alpha {}", ior, alpha));
    }
  }
}

// The balanced tier divides a rough dielectric's multiple scattering between reflection and
// transmission as the microsurface walk does: its reflected albedo from 0 to 80 degrees is the
// CPU walk's (tests/support/MicrosurfaceWalk.h, Heitz et al. 2016) within 0.01, for IOR 1.33 and
// 1.5 and alpha 0.25 to 1. Turquin's split in proportion to single scattering reflected 0.236
// where the walk reflects 0.063 (alpha 1, mu 0.15, IOR 1.53; issue 39).
TEST(Furnace, RoughDielectricReflectsWhatTheMicrosurfaceWalkReflects) {
  for (const char* ior : {"1.33", "1.5"}) {
    for (const char* alpha : {"0.25", "0.5", "1"}) {
      Context context;
      ir::Material m = single(context, bsdfDocument(fmt::format("  <dielectric_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                                "    <input name=\"ior\" type=\"float\" value=\"{}\" />\n"
                                                                "    <input name=\"scatter_mode\" type=\"string\" value=\"RT\" />\n"
                                                                "    <input name=\"roughness\" type=\"vector2\" value=\"{}, {}\" />\n"
                                                                "  </dielectric_bsdf>\n",
                                                                ior, alpha, alpha)));
      const std::vector<rt::Albedo> albedo = furnace(m, viewsTo80(), 65536);
      ASSERT_EQ(albedo.size(), 9u);
      for (size_t k = 0; k < albedo.size(); ++k) {
        const double degrees = 10.0 * double(k), t = degrees * 3.14159265358979 / 180.0;
        const walk::Albedo cpu = walk::albedo({std::sin(t), 0.0, std::cos(t)}, std::stod(alpha), std::stod(ior),
                                              [](double) { return 1.0; }, 1 << 16, 11 + k);
        const double noise = 4.0 * (albedo[k].reflectedError.x + std::sqrt(cpu.reflected * (1.0 - cpu.reflected) / 65536.0));
        EXPECT_NEAR(albedo[k].reflected.x, cpu.reflected, 0.01 + noise)
            << "IOR " << ior << ", alpha " << alpha << ", " << degrees << " degrees";
      }
    }
  }
}

// Balanced returns the energy single scattering loses in lobes shaped as multiple scattering
// (mxc_ms_lobe: rougher copies, reflection and refraction apart), not as a brighter copy of the
// specular peak: f cos on 52 direction pairs (views at 0 to 80 degrees; lights across and in the
// plane of incidence, reflected and transmitted, as `mxc bench accuracy`) is the reference
// walk's within 0.03 (RMS over the reference's RMS) for a rough metal and a rough glass, where
// the scaled copy was 0.094 and 0.049 off (issue 39). And the default base under a rough coat
// (coat_roughness 0.3): its Fresnel meets the view refracted into the coat (OpenPBR eq.
// refracted_coat_dir), where at the outside angle it put 15% more than the walk into the mirror
// direction at 80 degrees (0.149 off before, 0.010 after).
TEST(Eval, BalancedFCosFollowsTheWalk) {
  auto direction = [](double thetaDeg, double phiDeg) {
    const double t = thetaDeg * 3.14159265358979 / 180.0, p = phiDeg * 3.14159265358979 / 180.0;
    return glm::vec3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
  };
  std::vector<rt::DirectionPair> pairs;
  for (double view : {0.0, 30.0, 60.0, 80.0}) {
    for (double theta : {15.0, 45.0, 75.0}) {
      for (double phi : {0.0, 90.0, 180.0}) pairs.push_back({direction(view, 0.0), direction(theta, phi)});
    }
    for (double theta : {135.0, 165.0}) {
      for (double phi : {0.0, 180.0}) pairs.push_back({direction(view, 0.0), direction(theta, phi)});
    }
  }
  // The walk's estimate: the pairs 64 times over in each of 256 dispatches, 16384 walks a pair.
  constexpr size_t kReplicas = 64;
  std::vector<rt::DirectionPair> replicated;
  for (size_t r = 0; r < kReplicas; ++r) replicated.insert(replicated.end(), pairs.begin(), pairs.end());
  auto luminance = [](const glm::vec4& v) { return 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z; };
  const struct {
    const char* name;
    std::string inputs;
  } materials[] = {
      {"rough metal", "    <input name=\"base_metalness\" type=\"float\" value=\"1\" />\n"
                      "    <input name=\"specular_roughness\" type=\"float\" value=\"0.6\" />\n"},
      {"rough glass", "    <input name=\"transmission_weight\" type=\"float\" value=\"1\" />\n"
                      "    <input name=\"specular_roughness\" type=\"float\" value=\"0.5\" />\n"},
      {"rough coat", "    <input name=\"coat_weight\" type=\"float\" value=\"1\" />\n"
                     "    <input name=\"coat_roughness\" type=\"float\" value=\"0.3\" />\n"},
  };
  for (const auto& material : materials) {
    Context context;
    ir::Material m = single(context, openPbrDocument(material.inputs));
    const std::vector<glm::vec4> walk = evaluate(m, replicated, Accuracy::Reference, 256);
    const std::vector<glm::vec4> balanced = evaluate(m, pairs);
    ASSERT_EQ(walk.size(), replicated.size());
    ASSERT_EQ(balanced.size(), pairs.size());
    std::vector<double> reference(pairs.size(), 0.0);
    for (size_t i = 0; i < walk.size(); ++i) reference[i % pairs.size()] += luminance(walk[i]) / double(kReplicas);
    double error = 0.0, signal = 0.0;
    for (size_t i = 0; i < pairs.size(); ++i) {
      error += (luminance(balanced[i]) - reference[i]) * (luminance(balanced[i]) - reference[i]);
      signal += reference[i] * reference[i];
    }
    ASSERT_GT(signal, 0.0) << material.name;
    EXPECT_LT(std::sqrt(error / signal), 0.03) << material.name;
  }
}

// A scattering half-space (OpenPBR "Subsurface") under its interface and under a coat, and a
// glossy-diffuse base under a denser coat, against the reference walk's furnace at 0 to 75
// degrees (131,072 walks a view). The diffuse lobe of subsurface_color stayed at C while the walk
// rises towards grazing views (0.809 to 0.862 for pearl's red), and the coat's darkening,
// exact for a Lambertian in the coat, darkened a base less dense than the coat (whose light
// fills only part of the coat) by 0.03 too much, and a half-space (which sends its light up
// steeper and returns more of what comes back at grazing angles) by 0.08: mean absolute errors
// over views and channels 0.0073, 0.082 and 0.030 before mxc_subsurface.glsl and the coat's
// escape cone, 0.0010, 0.0097 and 0.0047 after (issue 39).
TEST(Furnace, SubsurfaceAndDarkeningFollowTheWalk) {
  const std::string pearl =
      "    <input name=\"base_color\" type=\"color3\" value=\"0.8, 0.75, 0.7\" />\n"
      "    <input name=\"specular_roughness\" type=\"float\" value=\"0.35\" />\n"
      "    <input name=\"subsurface_weight\" type=\"float\" value=\"1\" />\n"
      "    <input name=\"subsurface_color\" type=\"color3\" value=\"0.8, 0.75, 0.7\" />\n"
      "    <input name=\"subsurface_radius_scale\" type=\"color3\" value=\"0.3, 0.5, 0.3\" />\n";
  const struct {
    const char* name;
    std::string inputs;
    double bound;  // on the mean absolute error
  } cases[] = {
      {"subsurface", pearl, 0.002},
      {"subsurface under a coat of 1.68",
       pearl + "    <input name=\"coat_weight\" type=\"float\" value=\"1\" />\n"
               "    <input name=\"coat_roughness\" type=\"float\" value=\"0.15\" />\n"
               "    <input name=\"coat_ior\" type=\"float\" value=\"1.68\" />\n",
       0.012},
      {"glossy-diffuse under a rough coat of 1.6",
       "    <input name=\"coat_weight\" type=\"float\" value=\"1\" />\n"
       "    <input name=\"coat_roughness\" type=\"float\" value=\"0.3\" />\n",
       0.006},
  };
  const std::vector<glm::vec3> views = {viewAt(0.0), viewAt(30.0), viewAt(60.0), viewAt(75.0)};
  for (const auto& c : cases) {
    Context context;
    ir::Material m = single(context, openPbrDocument(c.inputs));
    const std::vector<rt::Albedo> walk = furnace(m, views, 1u << 17, {}, Accuracy::Reference);
    const std::vector<rt::Albedo> balanced = furnace(m, views, 1u << 18);
    ASSERT_EQ(walk.size(), views.size()) << c.name;
    ASSERT_EQ(balanced.size(), views.size()) << c.name;
    double error = 0.0, noise = 0.0;
    for (size_t v = 0; v < views.size(); ++v) {
      for (int k = 0; k < 3; ++k) {
        error += std::abs(double(balanced[v].total()[k]) - double(walk[v].total()[k])) / 12.0;
        noise += double(walk[v].reflectedError[k] + walk[v].transmittedError[k]) / 12.0;
      }
    }
    std::printf("%s: mean absolute error %.4f, the walk's standard error %.4f\n", c.name, error, noise);
    EXPECT_LT(error, c.bound + 2.0 * noise) << c.name << " (the walk's standard error " << noise << ")";
  }
}

// Lavapipe cuts a loop nest after 65535 iterations in an invocation (runtime/Evaluator.h), and a
// closure's sample runs its lobe loops inside the stage's sample loop: a coat over a fuzz over
// a glossy-diffuse base takes about 16 iterations a sample, so 4096 samples per invocation were
// cut after about 4000. The furnace threw, and the sampler returned the cut samples as failed
// draws (6% of them at 80 degrees, which the sampling test took for a wrong pdf; issue 39).
// Asked to draw 4096 per dispatch, both now run a cut dispatch again in smaller ones: the
// furnace agrees with one drawn in the default dispatches, and the sampler's failed draws are
// the few the pdf leaves out (its mass at 80 degrees is 0.993).
TEST(Furnace, LongSamplesAreDrawnWholeInSmallerDispatches) {
  Context context;
  ir::Material m = single(context, openPbrDocument("    <input name=\"specular_roughness\" type=\"float\" value=\"0.4\" />\n"
                                                   "    <input name=\"coat_weight\" type=\"float\" value=\"1\" />\n"
                                                   "    <input name=\"coat_roughness\" type=\"float\" value=\"0.3\" />\n"
                                                   "    <input name=\"fuzz_weight\" type=\"float\" value=\"1\" />\n"));
  const std::vector<glm::vec3> views = {viewAt(0.0), viewAt(80.0)};
  constexpr uint32_t kSamples = 1u << 18;  // 4096 per invocation
  Prepared furnaceShader = prepare(m, glsl::ShaderKind::Furnace);
  ASSERT_TRUE(furnaceShader.ok());
  rt::FurnaceEstimator estimator(Device::get().context, Device::get().tables, *furnaceShader.resources,
                                 furnaceShader.shader.interface, furnaceShader.words);
  const std::vector<rt::Albedo> byDefault = estimator.estimate(views, kSamples, 3);
  estimator.setSamplesPerDispatch(4096);
  const std::vector<rt::Albedo> asked = estimator.estimate(views, kSamples, 5);
  ASSERT_EQ(byDefault.size(), views.size());
  ASSERT_EQ(asked.size(), views.size());
  for (size_t v = 0; v < views.size(); ++v) {
    for (int c = 0; c < 3; ++c) {
      const float se = std::hypot(byDefault[v].reflectedError[c] + byDefault[v].transmittedError[c],
                                  asked[v].reflectedError[c] + asked[v].transmittedError[c]);
      EXPECT_GT(asked[v].total()[c], 0.5f);
      EXPECT_NEAR(asked[v].total()[c], byDefault[v].total()[c], 5.0f * se) << "view " << v << ", channel " << c;
    }
  }
  Prepared sampleShader = prepare(m, glsl::ShaderKind::Sample);
  ASSERT_TRUE(sampleShader.ok());
  rt::DirectionSampler sampler(Device::get().context, Device::get().tables, *sampleShader.resources,
                               sampleShader.shader.interface, sampleShader.words);
  sampler.setSamplesPerDispatch(4096);
  const std::vector<std::vector<rt::SampledDirection>> drawn = sampler.sample(views, kSamples);
  ASSERT_EQ(drawn.size(), views.size());
  for (const auto& view : drawn) {
    ASSERT_EQ(view.size(), size_t{kSamples});
    size_t failed = 0;
    for (const rt::SampledDirection& d : view) failed += d.kind == rt::SampledDirection::Kind::None ? 1 : 0;
    EXPECT_LT(double(failed), 0.015 * kSamples);
  }
}

// A hair fibre's albedo is exactly sum_p Ap (Chiang et al. 2016 eq. 3; its Mp and Np are
// normalised). Seen across the fibre (theta_o = 0) at its middle (h = 0): Fresnel at normal
// incidence, a chord of 2 radii (T = exp(-2 sigma_a)), and the geometric series of paths
// longer than TRT; on every tier.
TEST(Furnace, HairAlbedoIsItsAttenuationsAcrossTheFibre) {
  Context context;
  ir::Material m = single(context, bsdfDocument("  <chiang_hair_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                "    <input name=\"absorption_coefficient\" type=\"vector3\" value=\"0, 0.5, 2\" />\n"
                                                "  </chiang_hair_bsdf>\n"));
  const double eta = 1.55;
  const double f = std::pow((eta - 1.0) / (eta + 1.0), 2.0);
  for (Accuracy accuracy : {Accuracy::Fast, Accuracy::Balanced, Accuracy::Reference}) {
    std::vector<rt::Albedo> a = furnace(m, {viewAt(0)}, 65536, {}, accuracy);
    ASSERT_EQ(a.size(), 1u);
    const float sigma[3] = {0.0f, 0.5f, 2.0f};
    for (int ch = 0; ch < 3; ++ch) {
      const double t = std::exp(-2.0 * sigma[ch]);
      const double a1 = (1.0 - f) * (1.0 - f) * t;
      const double a2 = a1 * t * f;
      const double expected = f + a1 + a2 + a2 * t * f / (1.0 - t * f);
      const float total = a[0].total()[ch];
      const float error = a[0].reflectedError[ch] + a[0].transmittedError[ch];
      EXPECT_NEAR(total, expected, 4.0f * error + 2e-3f) << "channel " << ch << ", tier " << int(accuracy);
    }
  }
}

// Helmholtz reciprocity of single-scattering reflection (2.4): f(o, i) = f(i, o), so
// fcos(o, i) / |i.z| = fcos(i, o) / |o.z|.
TEST(Eval, ReflectionIsReciprocal) {
  Context context;
  ir::Material m = single(context, bsdfDocument("  <conductor_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                "    <input name=\"roughness\" type=\"vector2\" value=\"0.3, 0.1\" />\n"
                                                "  </conductor_bsdf>\n"));
  std::vector<rt::DirectionPair> pairs;
  for (int k = 0; k < 16; ++k) {
    const float a = 0.37f * float(k), b = 1.3f + 0.71f * float(k);
    glm::vec3 o = glm::normalize(glm::vec3(std::cos(a), std::sin(a), 0.3f + 0.1f * float(k % 5)));
    glm::vec3 i = glm::normalize(glm::vec3(std::cos(b), std::sin(b), 0.5f + 0.1f * float(k % 4)));
    pairs.push_back({o, i});
    pairs.push_back({i, o});
  }
  // Single scattering (the fast tier): balanced's compensation depends on wo alone and is not
  // reciprocal (physics notes 2.4).
  std::vector<glm::vec4> f = evaluate(m, pairs, Accuracy::Fast);
  ASSERT_EQ(f.size(), pairs.size());
  for (size_t k = 0; k < pairs.size(); k += 2) {
    for (int c = 0; c < 3; ++c) {
      const float forward = f[k][c] / pairs[k].wi.z;
      const float backward = f[k + 1][c] / pairs[k + 1].wi.z;
      EXPECT_GT(forward, 0.0f);
      EXPECT_NEAR(forward, backward, 1e-4f * std::max(forward, 1.0f)) << "pair " << k / 2;
    }
  }
}

// OpenPBR "Fuzz" (Zeltner et al. 2022): mu_i f = F R(mu_o) D with D a normalised density, so f cos
// integrated over the hemisphere is F R. The integral is taken by quadrature of the evaluated
// lobe, which checks D's normalisation, and compared with the furnace, whose estimate f / pdf is
// R for every sampled direction (so it pins R, not the sampler). At fuzz_roughness 1 both must
// match the authors' volumetric table, row alpha = 1: R = 0.55034, 0.44209 and 0.34187 at
// mu = 12/31, 20/31 and 1; the analytic fit stays within 0.005 of it (0.0043 at mu = 20/31).
TEST(Eval, FuzzIntegratesToItsReflectance) {
  struct Case {
    const char* roughness;
    float mu;
    float table;  // < 0: not checked against the table
  };
  for (const Case& c : {Case{"1", 12.0f / 31.0f, 0.55034f}, Case{"1", 20.0f / 31.0f, 0.44209f}, Case{"1", 1.0f, 0.34187f},
                        Case{"0.5", 0.3f, -1.0f}, Case{"0.5", 0.9f, -1.0f}}) {
    Context context;
    ir::Material m = single(context, bsdfDocument(fmt::format("  <sheen_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                              "    <input name=\"roughness\" type=\"float\" value=\"{}\" />\n"
                                                              "    <input name=\"mode\" type=\"string\" value=\"zeltner\" />\n"
                                                              "  </sheen_bsdf>\n",
                                                              c.roughness)));
    // wo off the x axis, so the LTC frame has to follow it.
    const float s = std::sqrt(std::max(0.0f, 1.0f - c.mu * c.mu));
    const glm::vec3 wo(s * std::cos(1.1f), s * std::sin(1.1f), c.mu);
    // Midpoint rule in (mu_i, phi): d omega = d mu_i d phi.
    const int nMu = 128, nPhi = 256;
    std::vector<rt::DirectionPair> pairs;
    for (int i = 0; i < nMu; ++i) {
      const float mu = (float(i) + 0.5f) / float(nMu);
      const float sin = std::sqrt(1.0f - mu * mu);
      for (int j = 0; j < nPhi; ++j) {
        const float phi = 2.0f * 3.14159265f * (float(j) + 0.5f) / float(nPhi);
        pairs.push_back({wo, glm::vec3(sin * std::cos(phi), sin * std::sin(phi), mu)});
      }
    }
    std::vector<glm::vec4> f = evaluate(m, pairs);
    ASSERT_EQ(f.size(), pairs.size());
    double sum = 0.0;
    for (const glm::vec4& v : f) {
      ASSERT_TRUE(std::isfinite(v.x) && v.x >= 0.0f);
      sum += v.x;
    }
    const float integral = float(sum * (2.0 * 3.14159265358979 / nPhi) / nMu);
    std::vector<rt::Albedo> albedo = furnace(m, {wo}, 4096);
    ASSERT_EQ(albedo.size(), 1u);
    const std::string what = fmt::format("fuzz roughness {} at mu = {}", c.roughness, c.mu);
    EXPECT_NEAR(integral, albedo[0].reflected.x, 2e-3f + 4.0f * albedo[0].reflectedError.x) << what;
    if (c.table >= 0.0f) {
      EXPECT_NEAR(albedo[0].reflected.x, c.table, 5e-3f) << what;
    }
  }
}

// Zeltner et al. 2022 fit their lobe to fibres that scatter light back towards where it came
// from: away from the normal, the lobe leans to wo's side (b < 0 in M^-1), so the retro-reflection
// direction gets more than the mirror direction. At mu = 0.3, roughness 0.5 the fit gives
// a = 0.416, b = -0.088 and a ratio (|t_mirror| / |t_retro|)^4 = 1.40. The quadrature above cannot
// see the lobe's orientation (any rotation integrates to the same R); this does.
TEST(Eval, FuzzLeansBackTowardsTheViewer) {
  Context context;
  ir::Material m = single(context, bsdfDocument("  <sheen_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                                "    <input name=\"roughness\" type=\"float\" value=\"0.5\" />\n"
                                                "    <input name=\"mode\" type=\"string\" value=\"zeltner\" />\n"
                                                "  </sheen_bsdf>\n"));
  const float mu = 0.3f, s = std::sqrt(1.0f - mu * mu);
  std::vector<rt::DirectionPair> pairs;
  for (float phi : {0.0f, 2.0f, 4.0f}) {
    const glm::vec3 wo(s * std::cos(phi), s * std::sin(phi), mu);
    pairs.push_back({wo, wo});                                // back to the viewer
    pairs.push_back({wo, glm::vec3(-wo.x, -wo.y, wo.z)});  // the mirror direction
  }
  std::vector<glm::vec4> f = evaluate(m, pairs);
  ASSERT_EQ(f.size(), pairs.size());
  for (size_t k = 0; k < pairs.size(); k += 2) {
    ASSERT_GT(f[k + 1].x, 0.0f);
    EXPECT_NEAR(f[k].x / f[k + 1].x, 1.40f, 0.02f) << "view " << k / 2;
  }
}

// OpenPBR eq. fuzz-layering-approx: F f_fuzz + (1 - F E_fuzz) f_base, the base untinted by the
// fuzz colour, on the fast tier: over a white base (E_base = 1), E = 1 - (1 - fuzz_color) E_fuzz,
// so white fuzz keeps the furnace at 1 and a 0.5 grey fuzz at roughness 1, normal view, gives
// 1 - 0.5 * 0.34187 (the authors' table). The balanced tier also returns to the base what the
// fuzz reflects of the base's light (mxc_fuzz_darkening), as the reference walk does: white fuzz
// still keeps the furnace at 1, and grey fuzz over a white base, and white fuzz over a grey
// one, are the walk's within 0.005 at 0, 45 and 75 degrees (albedo scaling alone: up to 0.03
// above it; issue 39).
TEST(Furnace, FuzzLayerPassesWhatItDoesNotReflectUntinted) {
  const std::vector<glm::vec3> views = {viewAt(0), viewAt(45), viewAt(75)};
  auto material = [](Context& context, const char* color, const char* base) {
    return single(context, openPbrDocument(fmt::format("    <input name=\"base_color\" type=\"color3\" value=\"{}\" />\n"
                                                       "    <input name=\"specular_weight\" type=\"float\" value=\"0\" />\n"
                                                       "    <input name=\"fuzz_weight\" type=\"float\" value=\"1\" />\n"
                                                       "    <input name=\"fuzz_roughness\" type=\"float\" value=\"1\" />\n"
                                                       "    <input name=\"fuzz_color\" type=\"color3\" value=\"{}\" />\n",
                                                       base, color)));
  };
  for (Accuracy tier : {Accuracy::Fast, Accuracy::Balanced}) {
    Context context;
    std::vector<rt::Albedo> albedo = furnace(material(context, "1, 1, 1", "1, 1, 1"), views, 65536, {}, tier);
    ASSERT_EQ(albedo.size(), views.size());
    for (const rt::Albedo& a : albedo) expectNear(a.total().y, 1.0f, a.reflectedError.y, 5e-4f, "white fuzz");
  }
  {
    // The grey fuzz on the fast tier: the fit's error.
    Context context;
    std::vector<rt::Albedo> albedo = furnace(material(context, "0.5, 0.5, 0.5", "1, 1, 1"), {viewAt(0)}, 65536, {}, Accuracy::Fast);
    ASSERT_EQ(albedo.size(), 1u);
    expectNear(albedo[0].total().y, 0.82907f, albedo[0].reflectedError.y, 5e-3f, "grey fuzz, fast");
  }
  for (const auto& [color, base] : {std::pair{"0.5, 0.5, 0.5", "1, 1, 1"}, std::pair{"1, 1, 1", "0.5, 0.5, 0.5"}}) {
    Context context;
    const ir::Material m = material(context, color, base);
    const std::vector<rt::Albedo> balanced = furnace(m, views, 65536, {}, Accuracy::Balanced);
    const std::vector<rt::Albedo> reference = furnace(m, views, 65536, {}, Accuracy::Reference);
    ASSERT_EQ(balanced.size(), views.size());
    ASSERT_EQ(reference.size(), views.size());
    for (size_t k = 0; k < views.size(); ++k) {
      expectNear(balanced[k].total().y, reference[k].total().y, reference[k].reflectedError.y, 5e-3f,
                 fmt::format("fuzz_color {} over base_color {}, view {}", color, base, k));
    }
  }
}

}  // namespace
}  // namespace mxc::test
