// Golden images: chosen corpus materials (both shading models, textured and procedural ones
// included) rendered on a sphere under the analytic sky and a key light, and on MaterialX's
// shader ball under the studio HDR image, committed under generated/images/ (shader balls in
// generated/images/shaderball/) as EXR and compared with an explicit per-pixel tolerance. A failing comparison writes the image and a difference image
// to the build folder (test-output/). `scripts/update-goldens` rewrites them.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "runtime/EnvironmentMap.h"
#include "runtime/ImageIO.h"
#include "runtime/MeshFile.h"
#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kGoldenMaterials = {
    "corpus/materialx/examples/OpenPbr/open_pbr_default.mtlx",
    "corpus/materialx/examples/OpenPbr/open_pbr_carpaint.mtlx",
    "corpus/materialx/examples/OpenPbr/open_pbr_glass.mtlx",
    "corpus/materialx/examples/OpenPbr/open_pbr_soapbubble.mtlx",
    "corpus/materialx/examples/OpenPbr/open_pbr_velvet.mtlx",
    "corpus/materialx/examples/StandardSurface/standard_surface_gold.mtlx",
    "corpus/materialx/examples/StandardSurface/standard_surface_wood_tiled.mtlx",
    "corpus/materialx/examples/StandardSurface/standard_surface_brick_procedural.mtlx",
    "corpus/materialx/examples/StandardSurface/standard_surface_marble_solid.mtlx",
};

// The tolerance: a pixel channel matches when |a - b| <= 0.02 + 0.05 |b| (linear radiance);
// at most 0.5% of the channels may miss (Monte Carlo outliers move when a sample direction
// changes by a rounding step), and the mean absolute difference must stay under 0.004.
constexpr float kAbsolute = 0.02f;
constexpr float kRelative = 0.05f;
constexpr double kOutlierShare = 0.005;
constexpr double kMeanDifference = 0.004;

rt::RenderSettings goldenSettings() {
  rt::RenderSettings s;
  s.width = s.height = 96;
  s.frames = 32;
  s.lights.push_back({rt::Light::Kind::Directional, glm::normalize(glm::vec3(-1.0f, 1.2f, 1.5f)), glm::vec3(1.0f), 2.0f});
  return s;
}

/// "" when `actual` matches `expected` within the tolerance; otherwise what is wrong. `diff`
/// receives the absolute difference, x10.
std::string compare(const rt::RgbaImage& actual, const rt::RgbaImage& expected, rt::RgbaImage& diff) {
  if (expected.width != actual.width || expected.height != actual.height) {
    return fmt::format("the golden is {}x{}, the image {}x{}", expected.width, expected.height, actual.width,
                       actual.height);
  }
  diff = rt::RgbaImage{actual.width, actual.height, std::vector<float>(actual.pixels.size(), 1.0f)};
  size_t outliers = 0, channels = 0;
  double sum = 0.0;
  for (size_t i = 0; i < actual.pixels.size(); ++i) {
    if (i % 4 == 3) continue;  // coverage is compared through the colour it scales
    const float a = actual.pixels[i], b = expected.pixels[i];
    const float d = std::abs(a - b);
    ++channels;
    sum += d;
    if (!(d <= kAbsolute + kRelative * std::abs(b))) ++outliers;  // also counts NaN
    diff.pixels[i] = 10.0f * d;
  }
  const double share = double(outliers) / double(channels);
  const double mean = sum / double(channels);
  if (share <= kOutlierShare && mean <= kMeanDifference) return "";
  return fmt::format("{:.3f}% of channels outside tolerance, mean difference {:.5f}", 100.0 * share, mean);
}

/// Compares `actual` with the golden `golden` (an .exr; a .png beside it for people), or
/// rewrites it under MXC_UPDATE_GOLDENS=1 when it no longer matches.
void checkGolden(const rt::RgbaImage& actual, const fs::path& golden) {
  ASSERT_FALSE(actual.pixels.empty());
  const std::string name = golden.stem().string();
  const char* update = std::getenv("MXC_UPDATE_GOLDENS");
  const bool updating = update && std::string(update) == "1";
  auto read = rt::readImage(golden);
  std::string problem;
  rt::RgbaImage diff;
  if (const auto* expected = std::get_if<rt::RgbaImage>(&read)) {
    problem = compare(actual, *expected, diff);
  } else {
    problem = std::get<std::string>(read);
  }
  if (updating) {
    // Only images that no longer match are rewritten (EXR files carry a time stamp, so an
    // unconditional rewrite would change every file).
    if (!problem.empty()) {
      fs::create_directories(golden.parent_path());
      ASSERT_FALSE(rt::writeImage(golden, actual).has_value());
      ASSERT_FALSE(rt::writeImage(fs::path(golden).replace_extension(".png"), actual).has_value());
    }
    GTEST_SKIP() << (problem.empty() ? "unchanged " : "updated ") << golden;
  }
  if (!problem.empty()) {
    const fs::path out = fs::current_path() / "test-output";
    fs::create_directories(out);
    rt::writeImage(out / (name + ".exr"), actual);
    if (!diff.pixels.empty()) rt::writeImage(out / (name + ".diff.png"), diff);
    ADD_FAILURE() << name << ": " << problem << "; the image and the difference (x10) are in " << out
                  << " (scripts/update-goldens rewrites the golden)";
  }
}

class ImageGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(ImageGolden, MatchesCommittedImage) {
  const fs::path document = sharedDir() / GetParam();
  Context context;
  std::vector<ir::Material> materials = lowerFile(context, document);
  ASSERT_EQ(materials.size(), 1u);
  const rt::RgbaImage actual = render(materials[0], goldenSettings(), document.parent_path());
  checkGolden(actual, sourceDir() / "generated/images" / (fs::path(GetParam()).stem().string() + ".exr"));
}

/// The shader ball under studio.exr, framed as `mxc render --mesh shaderball` frames it.
class ShaderBallGolden : public ::testing::TestWithParam<std::string> {};

TEST_P(ShaderBallGolden, MatchesCommittedImage) {
  const fs::path ballFile = sharedDir() / "conformance/materialx-tree/resources/Geometry/shaderball.glb";
  const fs::path studio = sharedDir() / "corpus/environments/studio.exr";
  if (!fs::exists(ballFile) || !fs::exists(studio)) GTEST_SKIP() << "no shader ball or studio.exr under " << sharedDir();
  static const rt::Mesh ball = [&] {
    auto loaded = rt::loadMesh(ballFile);
    return std::holds_alternative<rt::Mesh>(loaded) ? std::get<rt::Mesh>(loaded) : rt::Mesh{};
  }();
  ASSERT_FALSE(ball.indices.empty());
  static const std::unique_ptr<rt::EnvironmentMap> environment = [&] {
    std::vector<std::string> warnings;
    auto image = rt::EnvironmentMap::read(studio, 16384, warnings);
    return std::holds_alternative<rt::RgbaImage>(image)
               ? std::make_unique<rt::EnvironmentMap>(Device::get().context, std::move(std::get<rt::RgbaImage>(image)))
               : nullptr;
  }();
  ASSERT_TRUE(environment);
  rt::RenderSettings s;
  s.width = s.height = 128;
  s.frames = 48;
  s.environment = rt::Environment::Map;
  s.environmentMap = environment.get();
  s.environmentRotation = 90.0f;
  s.camera = rt::frameBounds(rt::meshBounds(ball), glm::vec3(0.0f, 0.0f, 1.0f), 45.0f, 1.0f);
  const fs::path document = sharedDir() / GetParam();
  Context context;
  std::vector<ir::Material> materials = lowerFile(context, document);
  ASSERT_EQ(materials.size(), 1u);
  const rt::RgbaImage actual = render(materials[0], s, document.parent_path(), Accuracy::Balanced, &ball);
  checkGolden(actual, sourceDir() / "generated/images/shaderball" / (fs::path(GetParam()).stem().string() + ".exr"));
}

INSTANTIATE_TEST_SUITE_P(Corpus, ShaderBallGolden, ::testing::ValuesIn(kGoldenMaterials),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return fs::path(param.param).stem().string();
                         });

INSTANTIATE_TEST_SUITE_P(Corpus, ImageGolden, ::testing::ValuesIn(kGoldenMaterials),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return fs::path(param.param).stem().string();
                         });

}  // namespace
}  // namespace mxc::test
