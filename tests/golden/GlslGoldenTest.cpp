// Golden shaders: the fragment shader of every corpus material, with the shader library files
// as #include lines (the material-specific part), is committed under generated/glsl/ and
// compared here. `scripts/update-goldens` rewrites them; review the diff before committing.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "support/MaterialSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

/// Every material's fragment shader, one after the other.
std::string shaders(const std::string& relative) {
  Context context;
  std::vector<ir::Material> materials = lowerFile(context, relative);
  std::string out;
  for (const ir::Material& m : materials) {
    CompileRequest request;
    request.expandLibrary = false;  // the material-specific part: library files as #include lines
    glsl::MaterialShader shader = buildShader(m, glsl::ShaderKind::Raster, request);
    out += "// ==== " + relative + ": material " + m.name + " ====\n" + shader.glsl.text;
  }
  if (context.diagnostics.hasErrors()) out += "\n" + context.diagnostics.format();
  return out;
}

class GlslGolden : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { ASSERT_EQ(::chdir(sharedDir().c_str()), 0); }
};

TEST_P(GlslGolden, MatchesCommittedShader) {
  const std::string relative = GetParam();
  fs::path golden = sourceDir() / "generated/glsl" / fs::path(relative).replace_extension(".frag");
  matchGolden(golden, shaders(relative), "generated/glsl/");
}

INSTANTIATE_TEST_SUITE_P(Corpus, GlslGolden, ::testing::ValuesIn(corpusDocuments()),
                         corpusTestName);

TEST(GlslGoldenFiles, NoStaleShaders) {
  for (const std::string& rel : staleGoldens(sourceDir() / "generated/glsl", ".frag")) {
    ADD_FAILURE() << "stale golden shader generated/glsl/" << rel;
  }
}

}  // namespace
}  // namespace mxc::test
