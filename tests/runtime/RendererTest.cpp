// The raster renderer (runtime/Renderer): a white Lambertian sphere disappears into the white
// furnace, and renderEach gives each object the image render() gives it alone. (That every
// corpus document renders to a finite image is checked by tests/corpus/SpecializationTest.cpp,
// which renders each of them.)

#include <gtest/gtest.h>

#include <cmath>

#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

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

// renderEach compiles every pipeline first, then draws each object alone into the one colour
// image, cleared between them: each image is what render() makes of that object, to the bit
// (the same frames, jitter and random numbers), and the progress counts each object's frames.
TEST(Renderer, RenderEachMatchesRenderingEachAlone) {
  Context context;
  std::vector<ir::Material> materials = lowerText(
      context, mtlx(R"(  <open_pbr_surface name="a" type="surfaceshader"><input name="base_metalness" type="float" value="1" /></open_pbr_surface>
  <surfacematerial name="A" type="material"><input name="surfaceshader" type="surfaceshader" nodename="a" /></surfacematerial>
  <open_pbr_surface name="b" type="surfaceshader"><input name="base_color" type="color3" value="0.9, 0.1, 0.1" /></open_pbr_surface>
  <surfacematerial name="B" type="material"><input name="surfaceshader" type="surfaceshader" nodename="b" /></surfacematerial>
  <open_pbr_surface name="c" type="surfaceshader"><input name="transmission_weight" type="float" value="1" /></open_pbr_surface>
  <surfacematerial name="C" type="material"><input name="surfaceshader" type="surfaceshader" nodename="c" /></surfacematerial>
)"));
  ASSERT_EQ(materials.size(), 3u) << context.diagnostics.format();
  rt::RenderSettings settings;
  settings.width = settings.height = 32;
  settings.frames = 3;
  settings.lights.push_back({rt::Light::Kind::Directional, glm::normalize(glm::vec3(-1, 1, 1)), glm::vec3(1.0f), 2.0f});
  std::vector<Prepared> prepared;
  for (const ir::Material& m : materials) prepared.push_back(prepare(m, glsl::ShaderKind::Raster));
  const rt::Mesh sphere = rt::makeSphere();
  std::vector<rt::SceneObject> objects;
  for (const Prepared& p : prepared) {
    ASSERT_TRUE(p.ok());
    objects.push_back({&sphere, settings.objectToWorld, p.resources.get(), &p.shader.interface, &p.words});
  }
  rt::Renderer renderer(Device::get().context, Device::get().tables);
  // Progress calls as (object, frames done); an image's arrival as (object, 0), after its frames.
  std::vector<std::pair<size_t, uint32_t>> calls;
  int checks = 0;
  std::vector<rt::RenderResult> each(objects.size());
  renderer.renderEach(
      objects, settings,
      [&](size_t object, rt::RenderResult&& image) {
        calls.emplace_back(object, 0);
        each[object] = std::move(image);
      },
      [&](size_t object, uint32_t frames) { calls.emplace_back(object, frames); }, [&] { ++checks; });
  EXPECT_EQ(checks, 1);
  ASSERT_EQ(calls.size(), 12u);
  for (size_t k = 0; k < calls.size(); ++k) {
    EXPECT_EQ(calls[k], std::make_pair(k / 4, uint32_t((k % 4 + 1) % 4))) << k;
  }
  for (size_t i = 0; i < objects.size(); ++i) {
    const rt::RgbaImage alone = renderer.render(sphere, *prepared[i].resources, prepared[i].shader.interface,
                                                prepared[i].words, settings).image;
    EXPECT_EQ(each[i].image.pixels, alone.pixels) << materials[i].name;
  }
  // The three differ (each image is its own material's, not the last one's or a sum).
  EXPECT_NE(each[0].image.pixels, each[1].image.pixels);
  EXPECT_NE(each[1].image.pixels, each[2].image.pixels);
}

}  // namespace
}  // namespace mxc::test
