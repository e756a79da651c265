// The closure's sampling against the pdf it reports (runtime/Evaluator: DirectionSampler and
// MaterialEvaluator). Directions drawn at a view are binned over the sphere, and each bin's count
// is compared with N times the integral of mxc_closure_pdf over the bin. A sampler that draws
// from another density than the one it reports biases every estimate that weighs samples by
// that pdf: one-sample MIS over lobes (Veach 1997, s. 9.2.4) and a Monte Carlo reference. The
// white furnace cannot see it when f / pdf is constant (a perfectly importance-sampled lobe).

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "support/ChiSquare.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Equal-area bins: z = cos theta uniform in [-1, 1], phi uniform.
constexpr int kZBins = 24;
constexpr int kPhiBins = 24;
constexpr int kSub = 24;  // quadrature points per bin and axis (midpoint rule; 8 is too few for the
                          // transmission lobe at normal incidence: its pdf mass came out 1.2% high)
constexpr uint32_t kSamples = 1u << 18;

struct Case {
  const char* name;
  const char* kind;  // "bsdf": a pbrlib BSDF node named bsdf; "openpbr": open_pbr_surface inputs
  const char* xml;
  std::vector<double> views;  // degrees from the normal, in the xz plane (> 90: from below)
  /// Bins and quadrature about the x axis instead of the normal: a hair fibre's own angles (its
  /// axis is the tangent, x). Its lobes are thin wedges around that axis, which bins on the
  /// surface's angles resolve only with far more quadrature points.
  bool aboutTangent = false;
};

/// A direction in the frame the bins are laid in: the surface's (z up), or with the tangent
/// x as the pole (z' = x, x' = y, y' = z).
glm::vec3 toBinFrame(const glm::vec3& w, bool aboutTangent) { return aboutTangent ? glm::vec3(w.y, w.z, w.x) : w; }
glm::vec3 fromBinFrame(const glm::vec3& r, bool aboutTangent) { return aboutTangent ? glm::vec3(r.z, r.x, r.y) : r; }

std::string document(const Case& c) {
  return std::string(c.kind) == "bsdf" ? bsdfDocument(c.xml) : openPbrDocument(c.xml);
}

int binOf(const glm::vec3& w) {
  const double z = std::clamp(double(w.z), -1.0, 1.0);
  double phi = std::atan2(double(w.y), double(w.x));  // (-pi, pi]
  if (phi < 0.0) phi += 2.0 * kPi;
  const int iz = std::min(int((z + 1.0) * 0.5 * kZBins), kZBins - 1);
  const int ip = std::min(int(phi / (2.0 * kPi) * kPhiBins), kPhiBins - 1);
  return iz * kPhiBins + ip;
}

class Sampling : public ::testing::TestWithParam<Case> {};

TEST_P(Sampling, DrawsTheDensityItReports) {
  const Case& c = GetParam();
  Context context;
  std::vector<ir::Material> materials = lowerText(context, document(c));
  ASSERT_FALSE(context.diagnostics.hasErrors()) << context.diagnostics.format();
  ASSERT_EQ(materials.size(), 1u);
  const ir::Material& m = materials.front();

  std::vector<glm::vec3> views;
  for (double d : c.views) views.push_back(viewAt(d));
  std::vector<std::vector<rt::SampledDirection>> drawn = sampleDirections(m, views, kSamples);
  ASSERT_EQ(drawn.size(), views.size());

  for (size_t v = 0; v < views.size(); ++v) {
    const std::string what = fmt::format("{} at {} degrees", c.name, c.views[v]);
    // Observed counts of the continuous samples.
    const double n = double(drawn[v].size());
    std::vector<double> observed(kZBins * kPhiBins, 0.0);
    for (const rt::SampledDirection& s : drawn[v]) {
      ASSERT_NE(s.kind, rt::SampledDirection::Kind::Delta) << what << ": the cases have no delta lobe";
      if (s.kind != rt::SampledDirection::Kind::Continuous) continue;
      ASSERT_TRUE(std::isfinite(s.wi.x) && std::isfinite(s.wi.y) && std::isfinite(s.wi.z)) << what;
      ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-3f) << what;
      observed[binOf(toBinFrame(s.wi, c.aboutTangent))] += 1.0;
    }
    // Expected counts: N times the pdf integrated over each bin. Within a bin the quadrature runs
    // over theta (d omega = sin theta d theta d phi), not z: the bins next to the poles span 24
    // degrees of theta, and a lobe around the normal (transmission at normal incidence) is
    // narrower than that.
    std::vector<rt::DirectionPair> pairs;
    std::vector<double> weights;
    pairs.reserve(size_t{kZBins} * kPhiBins * kSub * kSub);
    for (int iz = 0; iz < kZBins; ++iz) {
      const double t0 = std::acos(-1.0 + 2.0 * (iz + 1) / kZBins), t1 = std::acos(-1.0 + 2.0 * iz / kZBins);
      for (int it = 0; it < kSub; ++it) {
        const double theta = t0 + (t1 - t0) * (it + 0.5) / kSub;
        const double weight = std::sin(theta) * (t1 - t0) / kSub * (2.0 * kPi / (kPhiBins * kSub));
        for (int ip = 0; ip < kPhiBins * kSub; ++ip) {
          const double phi = 2.0 * kPi * (ip + 0.5) / (kPhiBins * kSub);
          const glm::vec3 r(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                            float(std::cos(theta)));
          pairs.push_back({views[v], fromBinFrame(r, c.aboutTangent)});
          weights.push_back(weight);
        }
      }
    }
    std::vector<glm::vec4> f = evaluate(m, pairs);
    ASSERT_EQ(f.size(), pairs.size());
    std::vector<double> expected(kZBins * kPhiBins, 0.0);
    double mass = 0.0;
    for (size_t k = 0; k < pairs.size(); ++k) {
      ASSERT_TRUE(std::isfinite(f[k].w) && f[k].w >= 0.0f) << what;
      expected[binOf(toBinFrame(pairs[k].wi, c.aboutTangent))] += n * f[k].w * weights[k];
      mass += f[k].w * weights[k];
    }
    // The share of draws that give a continuous sample is the pdf's mass (a lobe's failed draws,
    // below the horizon for instance, are the rest): binomial, 5 standard deviations.
    double continuous = 0.0;
    for (double o : observed) continuous += o;
    const double sd = std::sqrt(n * std::max(mass * (1.0 - mass), 1e-6));
    EXPECT_NEAR(continuous, n * mass, 5.0 * sd + 0.01 * n * mass) << what << ": pdf mass " << mass;

    // Pearson's statistic over the bins expecting at least 20, the rest pooled. The quadrature
    // error of the expected counts must stay far below the counting noise (about 5% per bin).
    const PearsonResult test = pearson(observed, expected, 20.0);
    const double statistic = test.statistic;
    const int bins = test.bins;
    if (test.pooledExpected < 20.0) {
      EXPECT_LT(test.pooledObserved, 40.0 + 10.0 * test.pooledExpected) << what << ": samples where the pdf is about 0";
    }
    ASSERT_GT(bins, 10) << what;
    // z = 5: a false alarm once in about 3.5 million runs per view.
    const double limit = chiSquareQuantile(bins - 1, 5.0);
    EXPECT_LT(statistic, limit) << what << ": chi-square " << statistic << " over " << bins << " bins";
  }
}

const Case kCases[] = {
    {"conductor_anisotropic", "bsdf",
     "  <conductor_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"vector2\" value=\"0.5, 0.25\" />"
     "</conductor_bsdf>\n",
     {0, 50, 80}},
    {"dielectric_reflection", "bsdf",
     "  <dielectric_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"vector2\" value=\"0.4, 0.4\" />"
     "<input name=\"scatter_mode\" type=\"string\" value=\"R\" /></dielectric_bsdf>\n",
     {0, 50, 80}},
    {"dielectric_transmission", "bsdf",
     "  <dielectric_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"vector2\" value=\"0.4, 0.4\" />"
     "<input name=\"scatter_mode\" type=\"string\" value=\"RT\" /></dielectric_bsdf>\n",
     {0, 50, 80, 130}},
    {"generalized_schlick", "bsdf",
     "  <generalized_schlick_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"vector2\" "
     "value=\"0.4, 0.4\" /></generalized_schlick_bsdf>\n",
     {0, 60}},
    {"oren_nayar", "bsdf",
     "  <oren_nayar_diffuse_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"float\" value=\"0.5\" />"
     "</oren_nayar_diffuse_bsdf>\n",
     {0, 70}},
    {"burley", "bsdf",
     "  <burley_diffuse_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"float\" value=\"0.5\" />"
     "</burley_diffuse_bsdf>\n",
     {0, 70}},
    {"translucent", "bsdf", "  <translucent_bsdf name=\"bsdf\" type=\"BSDF\" />\n", {0, 70}},
    {"sheen_conty_kulla", "bsdf",
     "  <sheen_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"float\" value=\"0.4\" /></sheen_bsdf>\n",
     {0, 70}},
    {"fuzz_zeltner", "bsdf",
     "  <sheen_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness\" type=\"float\" value=\"0.5\" />"
     "<input name=\"mode\" type=\"string\" value=\"zeltner\" /></sheen_bsdf>\n",
     {0, 50, 80}},
    // Hair, binned about the fibre (x). Along x, views in the xz plane see it at offset h = 0,
    // from 0 to 80 degrees and (130) from the other side of the fibre.
    {"hair_chiang", "bsdf", "  <chiang_hair_bsdf name=\"bsdf\" type=\"BSDF\" />\n", {0, 50, 80, 130}, true},
    // Wide along the fibre, narrow around it: the lobes reach the fibre's axis as wedges.
    {"hair_chiang_wedges", "bsdf",
     "  <chiang_hair_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"roughness_R\" type=\"vector2\" value=\"0.3, 0.05\" />"
     "<input name=\"roughness_TT\" type=\"vector2\" value=\"0.3, 0.05\" /><input name=\"roughness_TRT\" "
     "type=\"vector2\" value=\"0.3, 0.05\" /></chiang_hair_bsdf>\n",
     {0, 50, 80}, true},
    // A fibre turned out of the view plane (offsets h != 0), tilted cuticles, absorbing, rough:
    // its axis is no longer x, so binned on the surface's angles.
    {"hair_chiang_offset_tilted", "bsdf",
     "  <chiang_hair_bsdf name=\"bsdf\" type=\"BSDF\"><input name=\"curve_direction\" type=\"vector3\" "
     "value=\"0.6, 0.8, 0\" /><input name=\"cuticle_angle\" type=\"float\" value=\"0.55\" />"
     "<input name=\"absorption_coefficient\" type=\"vector3\" value=\"0.2, 0.5, 1\" />"
     "<input name=\"roughness_R\" type=\"vector2\" value=\"0.3, 0.4\" /></chiang_hair_bsdf>\n",
     {20, 60}},
    {"openpbr_layered", "openpbr",
     "    <input name=\"base_diffuse_roughness\" type=\"float\" value=\"0.5\" />\n"
     "    <input name=\"specular_roughness\" type=\"float\" value=\"0.4\" />\n"
     "    <input name=\"coat_weight\" type=\"float\" value=\"0.7\" />\n"
     "    <input name=\"coat_roughness\" type=\"float\" value=\"0.3\" />\n"
     "    <input name=\"fuzz_weight\" type=\"float\" value=\"0.5\" />\n",
     {0, 45, 80}},
};

INSTANTIATE_TEST_SUITE_P(Lobes, Sampling, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace mxc::test
