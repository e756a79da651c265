// The environment image's mapping and sampling distribution on the CPU
// (runtime/EnvironmentDistribution): the conventions the shaders share, a density that
// integrates to 1, an alias table that draws each cell with its share, and a density that
// bounds the bilinear lookup (what keeps the closure's samples from being fireflies).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "runtime/EnvironmentDistribution.h"
#include "support/EnvironmentImages.h"

namespace mxc::rt {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(EnvironmentMapping, FollowsTheStatedConvention) {
  // The image's centre along -z, a quarter turn to the right along +x, the top row up.
  EXPECT_NEAR(equirectUv({0.0f, 0.0f, -1.0f}).x, 0.5f, 1e-6f);
  EXPECT_NEAR(equirectUv({0.0f, 0.0f, -1.0f}).y, 0.5f, 1e-6f);
  EXPECT_NEAR(equirectUv({1.0f, 0.0f, 0.0f}).x, 0.75f, 1e-6f);
  EXPECT_NEAR(equirectUv({-1.0f, 0.0f, 0.0f}).x, 0.25f, 1e-6f);
  EXPECT_NEAR(equirectUv({0.0f, 1.0f, 0.0f}).y, 0.0f, 1e-6f);
  EXPECT_NEAR(equirectUv({0.0f, -1.0f, 0.0f}).y, 1.0f, 1e-6f);
  // Round trips, and the poles give a finite u.
  for (float u : {0.05f, 0.3f, 0.5f, 0.77f, 0.99f}) {
    for (float v : {0.01f, 0.25f, 0.5f, 0.9f}) {
      const glm::vec2 back = equirectUv(equirectDirection({u, v}));
      EXPECT_NEAR(back.x, u, 1e-5f);
      EXPECT_NEAR(back.y, v, 1e-5f);
    }
  }
  EXPECT_TRUE(std::isfinite(equirectUv({0.0f, 1.0f, 0.0f}).x));
  // A quarter turn counter-clockwise seen from above takes what the map shows along +x to -z.
  const glm::vec3 w = environmentToWorld({1.0f, 0.0f, 0.0f}, float(kPi / 2));
  EXPECT_NEAR(w.x, 0.0f, 1e-6f);
  EXPECT_NEAR(w.z, -1.0f, 1e-6f);
  const glm::vec3 m = environmentToMap(environmentToWorld({0.3f, 0.5f, -0.8f}, 1.1f), 1.1f);
  EXPECT_NEAR(m.x, 0.3f, 1e-6f);
  EXPECT_NEAR(m.y, 0.5f, 1e-6f);
  EXPECT_NEAR(m.z, -0.8f, 1e-6f);
}

TEST(EnvironmentDistribution, DensityIntegratesToOneAndTheAliasTableDrawsIt) {
  for (uint32_t width : {64u, 2048u}) {  // 2048: cells at half the image's resolution
    const RgbaImage image = test::patchImage(width, 400.0f);
    const EnvironmentDistribution d = EnvironmentDistribution::build(image, 1024);
    ASSERT_EQ(d.width, std::min(width, 1024u));
    ASSERT_EQ(d.height, d.width / 2);
    const size_t n = d.cells.size();
    double integral = 0.0, solid = 0.0;
    std::vector<double> drawn(n, 0.0);  // probability of each cell through the alias table
    for (uint32_t j = 0; j < d.height; ++j) {
      solid += d.cellSolidAngle(j) * d.width;
      for (uint32_t i = 0; i < d.width; ++i) {
        const glm::vec4& c = d.cells[size_t{j} * d.width + i];
        integral += double(c.z) * d.cellSolidAngle(j);
        ASSERT_GE(c.x, 0.0f);
        ASSERT_LE(c.x, 1.0f);
        uint32_t alias;
        std::memcpy(&alias, &c.y, 4);
        ASSERT_LT(alias, n);
        drawn[size_t{j} * d.width + i] += double(c.x) / double(n);
        drawn[alias] += (1.0 - double(c.x)) / double(n);
      }
    }
    EXPECT_NEAR(solid, 4.0 * kPi, 1e-9);
    EXPECT_NEAR(integral, 1.0, 1e-4) << width;
    for (uint32_t j = 0; j < d.height; ++j) {
      for (uint32_t i = 0; i < d.width; ++i) {
        const size_t k = size_t{j} * d.width + i;
        const double want = double(d.cells[k].z) * d.cellSolidAngle(j);
        ASSERT_NEAR(drawn[k], want, 1e-6 + 1e-4 * want) << width << ": cell " << i << "," << j;
      }
    }
  }
}

TEST(EnvironmentDistribution, DensityBoundsTheBilinearLookup) {
  // A direction's luminance over its density is what one image sample contributes (times the
  // closure); where it is far above the image's power, that direction is a firefly for the
  // closure's samples, which MIS then weights near 1. With each cell's density bounding the
  // lookup it stays at most the bounding power, here about 2.5 times the power; with each
  // cell's own texel alone (the mean, at the image's resolution) it reaches 750 times beside the
  // patch (light interpolated from a bright texel into a dark cell).
  const RgbaImage image = test::patchImage(64, 400.0f);
  const EnvironmentDistribution d = EnvironmentDistribution::build(image);
  double highest = 0.0, power = 0.0;
  constexpr int kAcross = 1024, kDown = 512;
  for (int b = 0; b < kDown; ++b) {
    const double solidAngle = 2.0 * kPi / kAcross * (std::cos(kPi * b / kDown) - std::cos(kPi * (b + 1) / kDown));
    for (int a = 0; a < kAcross; ++a) {
      const glm::vec3 dir = equirectDirection({(float(a) + 0.5f) / kAcross, (float(b) + 0.5f) / kDown});
      const glm::vec3 l = equirectLookup(image, dir);
      const double lum = 0.2126 * l.x + 0.7152 * l.y + 0.0722 * l.z;
      power += lum * solidAngle;
      highest = std::max(highest, lum / double(d.pdf(dir)));
    }
  }
  EXPECT_LT(highest / power, 4.0) << "luminance / density peaks at " << highest << ", power " << power;
}

TEST(EnvironmentDistribution, BlackAndEmptyImagesHaveNothingToSample) {
  RgbaImage black{8, 4, std::vector<float>(8 * 4 * 4, 0.0f)};
  const EnvironmentDistribution d = EnvironmentDistribution::build(black);
  for (const glm::vec4& c : d.cells) EXPECT_EQ(c.z, 0.0f);
  const EnvironmentDistribution e = EnvironmentDistribution::build(RgbaImage{});
  ASSERT_EQ(e.cells.size(), 1u);
  EXPECT_EQ(e.cells[0].z, 0.0f);
  EXPECT_EQ(e.pdf({0.0f, 1.0f, 0.0f}), 0.0f);
}

}  // namespace
}  // namespace mxc::rt
