// An environment image on the device (runtime/EnvironmentMap) and in the renderer: its sampler
// draws the density it reports (the chi-square test of the closures' samplers, tests/runtime/
// SamplingTest.cpp), a white Lambertian under a constant image is white (the white furnace,
// with both strategies of the MIS), and a Lambertian sphere under a bright patch shows the
// irradiance the image gives, turned with --env-rotation.

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "runtime/EnvironmentMap.h"
#include "support/ChiSquare.h"
#include "support/EnvironmentImages.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

void expectSamplerDrawsItsDensity(const rt::RgbaImage& image, uint32_t binsAcross, const std::string& what) {
  rt::EnvironmentMap map(Device::get().context, image);
  const rt::EnvironmentDistribution& d = map.distribution();
  ASSERT_EQ(d.width % binsAcross, 0u) << what;
  const uint32_t binsDown = binsAcross / 2;
  ASSERT_EQ(d.height % binsDown, 0u) << what;
  constexpr uint32_t kSamples = 1u << 20;
  const std::vector<rt::EnvironmentMap::Drawn> drawn = map.sample(kSamples, 7);
  ASSERT_EQ(drawn.size(), kSamples);

  std::vector<double> observed(size_t{binsAcross} * binsDown, 0.0), expected(observed.size(), 0.0);
  size_t pdfMismatches = 0;
  for (const rt::EnvironmentMap::Drawn& s : drawn) {
    const glm::vec3 dir(s.sample);
    ASSERT_TRUE(std::isfinite(dir.x) && std::isfinite(dir.y) && std::isfinite(dir.z)) << what;
    ASSERT_NEAR(glm::length(dir), 1.0f, 1e-4f) << what;
    ASSERT_GT(s.sample.w, 0.0f) << what;
    // The density it was drawn with is the one the MIS weights read (mxc_env_pdf) and the one
    // the CPU gives: equal but for directions on a cell's edge, where rounding picks either.
    const float cpu = d.pdf(dir);
    if (std::abs(s.pdf - s.sample.w) > 1e-6f * s.sample.w || std::abs(cpu - s.sample.w) > 1e-6f * s.sample.w) {
      ++pdfMismatches;
    }
    const glm::vec2 uv = rt::equirectUv(dir);
    const uint32_t i = std::min(uint32_t(uv.x * float(binsAcross)), binsAcross - 1);
    const uint32_t j = std::min(uint32_t(uv.y * float(binsDown)), binsDown - 1);
    observed[size_t{j} * binsAcross + i] += 1.0;
  }
  EXPECT_LT(pdfMismatches, kSamples / 1000) << what;
  // Expected: N times the density integrated over the bin, exactly (piecewise constant on cells).
  const uint32_t cellsPerBinX = d.width / binsAcross, cellsPerBinY = d.height / binsDown;
  double mass = 0.0;
  for (uint32_t j = 0; j < d.height; ++j) {
    for (uint32_t i = 0; i < d.width; ++i) {
      const double p = double(d.cells[size_t{j} * d.width + i].z) * d.cellSolidAngle(j);
      expected[size_t{j / cellsPerBinY} * binsAcross + i / cellsPerBinX] += double(kSamples) * p;
      mass += p;
    }
  }
  ASSERT_NEAR(mass, 1.0, 1e-4) << what;
  const PearsonResult test = pearson(observed, expected, 20.0);
  if (test.pooledExpected < 20.0) {
    EXPECT_LT(test.pooledObserved, 40.0 + 10.0 * test.pooledExpected) << what;
  }
  ASSERT_GT(test.bins, 100) << what;
  // z = 5: a false alarm once in about 3.5 million runs.
  EXPECT_LT(test.statistic, chiSquareQuantile(test.bins - 1, 5.0))
      << what << ": chi-square " << test.statistic << " over " << test.bins << " bins";
}

TEST(EnvironmentMap, SamplerDrawsTheDensityItReports) {
  // Bins are the cells of the small image (2048 of them) and 16 x 16 cells of studio's.
  expectSamplerDrawsItsDensity(patchImage(64, 400.0f), 64, "a bright patch over a sky");
  const auto studio = sharedDir() / "corpus/environments/studio.exr";
  if (!std::filesystem::exists(studio)) GTEST_SKIP() << studio << " is not there";
  std::vector<std::string> warnings;
  auto read = rt::EnvironmentMap::read(studio, 8192, warnings);
  ASSERT_TRUE(std::holds_alternative<rt::RgbaImage>(read)) << std::get<std::string>(read);
  expectSamplerDrawsItsDensity(std::get<rt::RgbaImage>(read), 32, "studio.exr");
}

TEST(EnvironmentMap, BlackImageDrawsNothing) {
  rt::EnvironmentMap map(Device::get().context, rt::RgbaImage{4, 2, std::vector<float>(4 * 2 * 4, 0.0f)});
  for (const rt::EnvironmentMap::Drawn& s : map.sample(256, 1)) {
    EXPECT_EQ(s.sample.w, 0.0f);
    EXPECT_EQ(s.pdf, 0.0f);
  }
}

ir::Material lambertian(Context& context, float albedo) {
  std::vector<ir::Material> materials = lowerText(
      context, bsdfDocument(fmt::format("  <oren_nayar_diffuse_bsdf name=\"bsdf\" type=\"BSDF\">\n"
                                        "    <input name=\"color\" type=\"color3\" value=\"{0}, {0}, {0}\" />\n"
                                        "  </oren_nayar_diffuse_bsdf>\n",
                                        albedo)));
  EXPECT_EQ(materials.size(), 1u);
  return materials.empty() ? ir::Material{} : materials.front();
}

// A white Lambertian reflects a constant environment's radiance exactly. Under an image both
// strategies contribute to every pixel (the closure's samples and the image's), so this holds
// only when the MIS weights of the two sum to 1 everywhere.
TEST(EnvironmentMap, WhiteLambertianIsWhiteUnderAConstantImage) {
  Context context;
  const ir::Material m = lambertian(context, 1.0f);
  rt::EnvironmentMap map(Device::get().context, rt::RgbaImage{16, 8, std::vector<float>(16 * 8 * 4, 1.0f)});
  rt::RenderSettings settings;
  settings.width = settings.height = 48;
  settings.frames = 64;
  settings.environment = rt::Environment::Map;
  settings.environmentMap = &map;
  settings.environmentRotation = 37.0f;
  const rt::RgbaImage image = render(m, settings);
  ASSERT_FALSE(image.pixels.empty());
  double sum = 0.0;
  size_t covered = 0;
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      if (p[3] < 0.999f) continue;
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(p[c] > 0.5f && p[c] < 1.5f) << x << "," << y << ": " << p[c];
      sum += p[0] + p[1] + p[2];
      covered += 3;
    }
  }
  ASSERT_GT(covered, 3u * 48 * 48 / 4);
  EXPECT_NEAR(sum / double(covered), 1.0, 0.005);
}

/// The irradiance from map image `image` turned by `rotation` radians on a surface with normal
/// `n` (world), by quadrature over 4 x the image's resolution with the renderer's lookup.
double irradiance(const rt::RgbaImage& image, const glm::vec3& n, float rotation) {
  const int across = int(image.width) * 4, down = int(image.height) * 4;
  double e = 0.0;
  for (int b = 0; b < down; ++b) {
    const double solidAngle = 2.0 * kPi / across * (std::cos(kPi * b / down) - std::cos(kPi * (b + 1) / down));
    for (int a = 0; a < across; ++a) {
      const glm::vec3 m = rt::equirectDirection({(float(a) + 0.5f) / float(across), (float(b) + 0.5f) / float(down)});
      const float c = glm::dot(rt::environmentToWorld(m, rotation), n);
      if (c <= 0.0f) continue;
      const glm::vec3 l = rt::equirectLookup(image, m);
      e += double(l.x) * c * solidAngle;  // the red channel
    }
  }
  return e;
}

// A Lambertian sphere under a sky with a bright patch: each quarter of the sphere's disc has the
// radiance albedo / pi times the irradiance the image gives its normals, for two turns of the
// image (a turn the renderer ignored, or applied the other way, moves the highlight to another
// quarter).
TEST(EnvironmentMap, LambertianShowsTheIrradianceOfTheImage) {
  Context context;
  const float albedo = 0.8f;
  const ir::Material m = lambertian(context, albedo);
  const rt::RgbaImage image = patchImage(32, 200.0f);
  rt::EnvironmentMap map(Device::get().context, image);
  for (float degrees : {0.0f, 120.0f}) {
    rt::RenderSettings settings;
    settings.width = settings.height = 40;
    settings.frames = 256;
    settings.environment = rt::Environment::Map;
    settings.environmentMap = &map;
    settings.environmentRotation = degrees;
    const rt::RgbaImage rendered = render(m, settings);
    ASSERT_FALSE(rendered.pixels.empty());
    // Each pixel's normal: the camera's ray (draw(): eye at +3.4 z, 45 degrees) meets the unit sphere.
    const float tanHalf = std::tan(glm::radians(settings.camera.fovDegrees) * 0.5f);
    double got[4] = {}, want[4] = {};
    for (uint32_t y = 0; y < rendered.height; ++y) {
      for (uint32_t x = 0; x < rendered.width; ++x) {
        if (rendered.at(x, y)[3] < 0.999f) continue;
        const glm::vec3 eye = settings.camera.eye;
        const glm::vec3 d = glm::normalize(glm::vec3((2.0f * (float(x) + 0.5f) / float(rendered.width) - 1.0f) * tanHalf,
                                                     (1.0f - 2.0f * (float(y) + 0.5f) / float(rendered.height)) * tanHalf,
                                                     -1.0f));
        const float bd = glm::dot(eye, d), disc = bd * bd - (glm::dot(eye, eye) - 1.0f);
        if (disc < 0.05f) continue;  // near the silhouette the mesh's facets differ from the sphere
        const glm::vec3 n = glm::normalize(eye + d * (-bd - std::sqrt(disc)));
        const int quarter = (x < rendered.width / 2 ? 0 : 1) + (y < rendered.height / 2 ? 0 : 2);
        got[quarter] += rendered.at(x, y)[0];
        want[quarter] += albedo / kPi * irradiance(image, n, glm::radians(degrees));
      }
    }
    for (int q = 0; q < 4; ++q) {
      ASSERT_GT(want[q], 0.0);
      EXPECT_NEAR(got[q] / want[q], 1.0, 0.03) << "turned " << degrees << " degrees, quarter " << q << ": rendered "
                                                << got[q] << ", expected " << want[q];
    }
  }
}

}  // namespace
}  // namespace mxc::test
