// Glitter flakes (flake2d, flake3d: the rule in compiler/lower/StdlibRules.cpp, mxc_flake in
// compiler/glsl/library/mxc_procedural.glsl), measured on rendered images: the fraction of the
// surface the flakes cover is the `coverage` asked for, and their normals follow the GGX
// distribution of `roughness`.
//
// Each image is an unlit sphere whose red channel is 1 where a flake is (presence > 0), green a
// property of the flake there, blue 1 where the flake's id is positive. The flakes are about a
// pixel wide, so a 256 x 256 image sees some 20000 of them: the standard error of a fraction
// measured over the sphere is about 0.005.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

struct Counts {
  size_t surface = 0;  ///< pixels of the sphere
  size_t flakes = 0;   ///< of which a flake covers
  size_t green = 0;    ///< flake pixels whose green is 1
  size_t ids = 0;      ///< flake pixels whose id is positive
  size_t stray = 0;    ///< pixels with a positive id or green but no flake
};

/// Renders flake2d (texture coordinates) or flake3d (object position) with `inputs`, green
/// being 1 where `green` (a float node named "g", written against the flake node "f") is above 0.
Counts measure(bool planar, const std::string& inputs, const std::string& green) {
  const std::string category = planar ? "flake2d" : "flake3d";
  const std::string size = planar ? "0.004" : "0.02";
  const std::string body = fmt::format(
      "  <{0} name=\"f\" type=\"multioutput\">\n"
      "    <input name=\"size\" type=\"float\" value=\"{1}\"/>\n{2}"
      "  </{0}>\n"
      "  <ifgreater name=\"covered\" type=\"float\">\n"
      "    <input name=\"value1\" type=\"float\" nodename=\"f\" output=\"presence\"/>\n"
      "    <input name=\"value2\" type=\"float\" value=\"0\"/>\n"
      "    <input name=\"in1\" type=\"float\" value=\"1\"/><input name=\"in2\" type=\"float\" value=\"0\"/>\n"
      "  </ifgreater>\n{3}"
      "  <ifgreater name=\"green\" type=\"float\">\n"
      "    <input name=\"value1\" type=\"float\" nodename=\"g\"/>\n"
      "    <input name=\"value2\" type=\"float\" value=\"0\"/>\n"
      "    <input name=\"in1\" type=\"float\" value=\"1\"/><input name=\"in2\" type=\"float\" value=\"0\"/>\n"
      "  </ifgreater>\n"
      "  <convert name=\"idf\" type=\"float\"><input name=\"in\" type=\"integer\" nodename=\"f\" output=\"id\"/></convert>\n"
      "  <ifgreater name=\"identified\" type=\"float\">\n"
      "    <input name=\"value1\" type=\"float\" nodename=\"idf\"/>\n"
      "    <input name=\"value2\" type=\"float\" value=\"0\"/>\n"
      "    <input name=\"in1\" type=\"float\" value=\"1\"/><input name=\"in2\" type=\"float\" value=\"0\"/>\n"
      "  </ifgreater>\n"
      "  <combine3 name=\"c\" type=\"color3\">\n"
      "    <input name=\"in1\" type=\"float\" nodename=\"covered\"/>\n"
      "    <input name=\"in2\" type=\"float\" nodename=\"green\"/>\n"
      "    <input name=\"in3\" type=\"float\" nodename=\"identified\"/>\n"
      "  </combine3>\n"
      "  <surface_unlit name=\"surf\" type=\"surfaceshader\"><input name=\"emission_color\" type=\"color3\" nodename=\"c\"/></surface_unlit>\n"
      "  <surfacematerial name=\"M\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"surf\"/></surfacematerial>\n",
      category, size, inputs, green);
  Context context;
  std::vector<ir::Material> materials = lowerText(context, mtlx(body));
  EXPECT_EQ(materials.size(), 1u) << context.diagnostics.format();
  if (materials.size() != 1) return {};
  rt::RenderSettings settings;
  settings.width = settings.height = 256;
  settings.frames = 1;
  settings.environment = rt::Environment::None;
  const rt::RgbaImage image = render(materials[0], settings);
  EXPECT_FALSE(image.pixels.empty());
  Counts counts;
  float top = 0.0f;  // the unlit surface's emission scale: the value of a channel that is 1
  for (uint32_t i = 0; i < image.width * image.height; ++i) top = std::max(top, image.pixels[4 * i]);
  for (uint32_t i = 0; i < image.width * image.height; ++i) {
    const float* p = &image.pixels[4 * i];
    if (p[3] < 0.999f) continue;  // background and the sphere's outline
    ++counts.surface;
    const bool flake = p[0] > 0.5f * top;
    const bool greenOn = p[1] > 0.5f * top;
    const bool idOn = p[2] > 0.5f * top;
    counts.flakes += flake ? 1 : 0;
    counts.green += flake && greenOn ? 1 : 0;
    counts.ids += flake && idOn ? 1 : 0;
    counts.stray += !flake && (greenOn || idOn) ? 1 : 0;
  }
  return counts;
}

const char* const kNoGreen = "  <constant name=\"g\" type=\"float\"><input name=\"value\" type=\"float\" value=\"0\"/></constant>\n";

// The covered fraction is the coverage asked for: exactly none at 0 and all at 1, within 0.03
// between (the model's derivation leaves it at most 0.02 below; the rest is sampling error).
// Every flake has a positive id, and no id is positive where no flake is.
TEST(Flake, CoversTheFractionAsked) {
  for (bool planar : {true, false}) {
    for (float coverage : {0.0f, 0.1f, 0.25f, 0.5f, 0.75f, 0.9f, 1.0f}) {
      const Counts counts =
          measure(planar, fmt::format("    <input name=\"coverage\" type=\"float\" value=\"{}\"/>\n", coverage), kNoGreen);
      ASSERT_GT(counts.surface, 20000u) << "the sphere covers about 40% of the frame";
      const double covered = static_cast<double>(counts.flakes) / static_cast<double>(counts.surface);
      const std::string what = fmt::format("{} at coverage {}", planar ? "flake2d" : "flake3d", coverage);
      if (coverage == 0.0f) EXPECT_EQ(counts.flakes, 0u) << what;
      else if (coverage == 1.0f) EXPECT_EQ(counts.flakes, counts.surface) << what;
      else EXPECT_NEAR(covered, coverage, 0.03) << what;
      EXPECT_EQ(counts.ids, counts.flakes) << what;
      EXPECT_EQ(counts.stray, 0u) << what;
    }
  }
}

// Flake normals follow GGX with alpha = roughness^2: the inverse CDF in cos^2 theta is
// (1 - xi) / ((1 - xi) + alpha^2 xi) (Walter et al. 2007, eq. 35), decreasing in xi, so a
// fraction 1 - q of the flakes is tilted further from the normal than cos^2 theta_q =
// (1 - q) / ((1 - q) + alpha^2 q). The fraction of flake pixels beyond each quantile is measured (the tilt is independent of the
// flake's shape and size, so pixels weigh flakes fairly). Roughness 0 tilts none.
TEST(Flake, NormalsFollowTheGgxDistributionOfTheirRoughness) {
  for (bool planar : {true, false}) {
    for (float roughness : {0.0f, 0.4f, 0.8f}) {
      for (double q : {0.25, 0.5, 0.75}) {
        const double alpha = static_cast<double>(roughness) * roughness;
        const double cos2 = (1.0 - q) / ((1.0 - q) + alpha * alpha * q);
        // green: the flake's cos^2 theta to the surface normal is below cos^2 theta_q.
        const std::string green = fmt::format(
            "  <normal name=\"n\" type=\"vector3\"><input name=\"space\" type=\"string\" value=\"world\"/></normal>\n"
            "  <dotproduct name=\"cosine\" type=\"float\">\n"
            "    <input name=\"in1\" type=\"vector3\" nodename=\"f\" output=\"flakenormal\"/>\n"
            "    <input name=\"in2\" type=\"vector3\" nodename=\"n\"/>\n"
            "  </dotproduct>\n"
            "  <multiply name=\"cos2\" type=\"float\"><input name=\"in1\" type=\"float\" nodename=\"cosine\"/>"
            "<input name=\"in2\" type=\"float\" nodename=\"cosine\"/></multiply>\n"
            "  <subtract name=\"g\" type=\"float\"><input name=\"in1\" type=\"float\" value=\"{}\"/>"
            "<input name=\"in2\" type=\"float\" nodename=\"cos2\"/></subtract>\n",
            roughness == 0.0f ? 1.0 - 1e-5 : cos2);
        const Counts counts = measure(planar,
                                      fmt::format("    <input name=\"coverage\" type=\"float\" value=\"1\"/>\n"
                                                  "    <input name=\"roughness\" type=\"float\" value=\"{}\"/>\n",
                                                  roughness),
                                      green);
        ASSERT_GT(counts.flakes, 20000u);
        const double tilted = static_cast<double>(counts.green) / static_cast<double>(counts.flakes);
        const std::string what = fmt::format("{} at roughness {}, quantile {}", planar ? "flake2d" : "flake3d", roughness, q);
        if (roughness == 0.0f) EXPECT_EQ(counts.green, 0u) << what;
        else EXPECT_NEAR(tilted, 1.0 - q, 0.03) << what;
        if (roughness == 0.0f) break;  // one quantile says it
      }
    }
  }
}

}  // namespace
}  // namespace mxc::test
