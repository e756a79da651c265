// Replays the fuzz targets on the seed corpus (every .mtlx under ../shared/corpus, and
// tests/fuzz/seeds/ for the inline source, scene and mesh targets) and on every input the
// fuzzers found (tests/fuzz/regressions/), in the normal build and under the sanitizer build:
// each must come back without a crash or an exception. The seeds are checked to reach what they
// are for: the valid ones are read, the campaign's crash categories are refused with a message.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "FuzzTargets.h"
#include "cli/Scene.h"
#include "runtime/MeshFile.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> inputs() {
  std::vector<std::string> files;
  for (const std::string& doc : corpusDocuments()) files.push_back((sharedDir() / doc).string());
  const fs::path regressions = sourceDir() / "tests/fuzz/regressions";
  for (const auto& e : fs::directory_iterator(regressions)) {
    if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzRegression, TargetsReturn) {
  std::ifstream in(GetParam(), std::ios::binary);
  ASSERT_TRUE(in) << GetParam();
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  EXPECT_NO_THROW(fuzz::parseXml(data, bytes.size()));
  EXPECT_NO_THROW(fuzz::compileDocument(data, bytes.size()));
}

INSTANTIATE_TEST_SUITE_P(Inputs, FuzzRegression, ::testing::ValuesIn(inputs()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = fs::path(param.param).parent_path().filename().string() + "_" +
                                              fs::path(param.param).stem().string();
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

/// Every seed of a target's folder (tests/fuzz/seeds/<folder>), as "folder/file".
std::vector<std::string> seeds() {
  std::vector<std::string> files;
  for (const char* folder : {"inline", "scene", "mesh"}) {
    for (const auto& e : fs::directory_iterator(sourceDir() / "tests/fuzz/seeds" / folder)) {
      if (e.is_regular_file()) files.push_back(std::string(folder) + "/" + e.path().filename().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzSeed : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzSeed, TargetReturns) {
  const std::string bytes = readFileBytes(sourceDir() / "tests/fuzz/seeds" / GetParam());
  if (!GetParam().starts_with("inline/")) {
    ASSERT_FALSE(bytes.empty()) << GetParam();  // an empty source is a seed
  }
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  if (GetParam().starts_with("inline/")) {
    EXPECT_NO_THROW(fuzz::compileInlineSource(data, bytes.size()));
  } else if (GetParam().starts_with("scene/")) {
    EXPECT_NO_THROW(fuzz::readSceneJson(data, bytes.size()));
  } else {
    EXPECT_NO_THROW(fuzz::loadMeshFile(data, bytes.size()));
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, FuzzSeed, ::testing::ValuesIn(seeds()), [](const ::testing::TestParamInfo<std::string>& param) {
  std::string name = param.param;
  for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
});

// The mesh and scene seeds reach the readers: the valid ones load, each broken one is refused
// with a message about what is wrong (not a crash, not a silent success).
TEST(FuzzSeeds, ValidMeshesLoadAndBrokenOnesAreRefused) {
  const fs::path folder = sourceDir() / "tests/fuzz/seeds/mesh";
  for (const char* name : {"triangle.obj", "triangle.gltf", "triangle.glb", "quad_negative_indices.obj"}) {
    auto mesh = rt::loadMeshBytes(folder / name, readFileBytes(folder / name));
    ASSERT_TRUE(std::holds_alternative<rt::Mesh>(mesh)) << name << ": " << std::get<std::string>(mesh);
    EXPECT_GE(std::get<rt::Mesh>(mesh).vertices.size(), 3u) << name;
  }
  for (auto [name, why] : {std::pair{"position_nan.obj", "finite"}, {"position_inf.obj", "finite"},
                           {"index_beyond_an_integer.obj", ""}, {"huge_triangle.obj", ""},
                           {"buffer_beyond_the_file.gltf", ""}, {"no_faces.obj", ""}}) {
    auto mesh = rt::loadMeshBytes(folder / name, readFileBytes(folder / name));
    ASSERT_TRUE(std::holds_alternative<std::string>(mesh)) << name << " was read";
    EXPECT_NE(std::get<std::string>(mesh).find(why), std::string::npos) << name << ": " << std::get<std::string>(mesh);
  }
}

TEST(FuzzSeeds, ValidScenesReadAndBrokenOnesAreRefused) {
  const fs::path folder = sourceDir() / "tests/fuzz/seeds/scene";
  for (const char* name : {"minimal.json", "lights_and_environment.json", "scale_tiny.json", "scale_huge.json"}) {
    auto scene = cli::readSceneText(folder / name, readFileBytes(folder / name));
    EXPECT_TRUE(std::holds_alternative<cli::Scene>(scene)) << name << ": " << std::get<std::string>(scene);
  }
  for (auto [name, why] : {std::pair{"not_json.json", "not valid JSON"}, {"number_beyond_a_double.json", "beyond the range of a double"},
                           {"camera_far.json", "camera"}, {"camera_up_along_view.json", "camera"}}) {
    auto scene = cli::readSceneText(folder / name, readFileBytes(folder / name));
    ASSERT_TRUE(std::holds_alternative<std::string>(scene)) << name << " was read";
    EXPECT_NE(std::get<std::string>(scene).find(why), std::string::npos) << name << ": " << std::get<std::string>(scene);
  }
}

}  // namespace
}  // namespace mxc::test
