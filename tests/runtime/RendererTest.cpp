// The raster renderer (runtime/Renderer): every corpus document renders to a finite image, and
// a white Lambertian sphere disappears into the white furnace.

#include <gtest/gtest.h>

#include <cmath>

#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

class RenderCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(RenderCorpus, ImageIsFinite) {
  Context context;
  const fs::path path = sharedDir() / GetParam();
  std::vector<ir::Material> materials = lowerFile(context, path);
  ASSERT_FALSE(materials.empty());
  rt::RenderSettings settings;
  settings.width = settings.height = 24;
  settings.frames = 2;
  settings.lights.push_back({rt::Light::Kind::Directional, glm::normalize(glm::vec3(-1, 1, 1)), glm::vec3(1.0f), 2.0f});
  settings.lights.push_back({rt::Light::Kind::Point, glm::vec3(2, 0, 2), glm::vec3(1.0f), 4.0f});
  for (const ir::Material& m : materials) {
    rt::RgbaImage image = render(m, settings, path.parent_path());
    ASSERT_EQ(image.pixels.size(), 24u * 24u * 4u) << m.name;
    size_t bad = 0, negative = 0;
    for (float v : image.pixels) {
      bad += std::isfinite(v) ? 0 : 1;
      negative += v < 0.0f ? 1 : 0;
    }
    EXPECT_EQ(bad, 0u) << m.name << ": NaN or infinite pixel values";
    EXPECT_EQ(negative, 0u) << m.name << ": negative pixel values";
    EXPECT_GT(image.at(12, 12)[3], 0.0f) << m.name << ": the sphere does not cover the centre";
  }
  EXPECT_TRUE(Device::get().context.validationMessages().empty()) << Device::get().context.validationMessages().front();
}

INSTANTIATE_TEST_SUITE_P(Corpus, RenderCorpus, ::testing::ValuesIn(corpusDocuments()),
                         corpusTestName);

// A white Lambertian in a white environment reflects exactly the environment's radiance: every
// covered pixel is 1 (cosine sampling makes each sample's weight exactly 1), the background 0.
TEST(Renderer, WhiteLambertianVanishesInTheWhiteFurnace) {
  Context context;
  std::vector<ir::Material> materials = lowerText(
      context, bsdfDocument("  <oren_nayar_diffuse_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                            "    <input name=\"color\" type=\"color3\" value=\"1, 1, 1\" />\n"
                            "  </oren_nayar_diffuse_bsdf>\n"));
  ASSERT_EQ(materials.size(), 1u);
  rt::RenderSettings settings;
  settings.width = settings.height = 40;
  settings.frames = 4;
  settings.environment = rt::Environment::White;
  rt::RgbaImage image = render(materials[0], settings);
  ASSERT_FALSE(image.pixels.empty());
  size_t covered = 0;
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      // Edge pixels are partly covered over the jittered frames: radiance equals coverage.
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], p[3], 1e-4f) << x << "," << y;
      covered += p[3] > 0.999f ? 1 : 0;
    }
  }
  // The sphere (radius 1 at distance 3.4, 45 degree field of view) covers about 37% of the frame.
  EXPECT_GT(covered, 40u * 40u / 4);
  EXPECT_LT(covered, 40u * 40u / 2);
}

}  // namespace
}  // namespace mxc::test
