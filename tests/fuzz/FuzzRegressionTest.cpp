// Replays the fuzz targets on the seed corpus (every .mtlx under ../shared/corpus) and on every
// input the fuzzers found (tests/fuzz/regressions/), in the normal build and under the
// sanitizer build: each must come back without a crash or an exception.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "FuzzTargets.h"
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

}  // namespace
}  // namespace mxc::test
