// Every .mtlx document of the shared corpus and of the reference folders loads and resolves
// with zero errors: against mxc's built-in library, against MaterialX's own library folder
// alone, and with MaterialX's library layered over ours.

#include <gtest/gtest.h>

#include <algorithm>

#include "support/TestSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> corpusFiles() {
  std::vector<std::string> files;
  for (const fs::path& root : {sharedDir() / "corpus", sharedDir() / "reference", sourceDir() / "examples"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (entry.is_regular_file() && entry.path().extension() == ".mtlx") files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

enum class LibraryChoice { Builtin, MaterialX, Both };

/// The libraries of each choice, loaded once for the whole test program.
const lib::LibraryStack& libraryFor(LibraryChoice choice) {
  static Workspace builtin, materialx, both;
  static bool loaded = false;
  if (!loaded) {
    loaded = true;
    const std::string mx = (sharedDir() / "reference/materialx/libraries").string();
    EXPECT_TRUE(builtin.loadLibraries(true)) << builtin.diagnostics.format();
    EXPECT_TRUE(materialx.loadLibraries(false, {mx})) << materialx.diagnostics.format();
    EXPECT_TRUE(both.loadLibraries(true, {mx})) << both.diagnostics.format();
  }
  return choice == LibraryChoice::Builtin ? builtin.libraries : choice == LibraryChoice::MaterialX ? materialx.libraries : both.libraries;
}

class Corpus : public ::testing::TestWithParam<std::string> {
 protected:
  void check(LibraryChoice choice) {
    Workspace workspace;
    CompileRequest request;
    request.document = GetParam();
    request.libraries = &libraryFor(choice);
    Compiler compiler(workspace, request);
    const resolve::ResolvedDocument* r = compiler.resolved();
    ASSERT_NE(r, nullptr) << workspace.diagnostics.format();
    EXPECT_FALSE(workspace.diagnostics.hasErrors()) << workspace.diagnostics.format();
    // Material documents (examples and presets) bind a shader to each material; the files under
    // an include/ folder are pieces other documents include (shared nodes), with no material.
    const std::string& path = GetParam();
    const bool piece = path.find("/include/") != std::string::npos;
    if (!piece && (path.find("examples/") != std::string::npos || path.find("openpbr-presets") != std::string::npos)) {
      EXPECT_FALSE(r->materials.empty());
      for (const auto& m : r->materials) EXPECT_FALSE(m.shaders.empty()) << m.node->name();
    }
  }
};

TEST_P(Corpus, ResolvesWithTheBuiltinLibrary) { check(LibraryChoice::Builtin); }
TEST_P(Corpus, ResolvesWithMaterialXLibrary) { check(LibraryChoice::MaterialX); }
TEST_P(Corpus, ResolvesWithMaterialXOverBuiltin) { check(LibraryChoice::Both); }

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  fs::path path(info.param);
  std::string rel = path.string().rfind(sourceDir().string(), 0) == 0 ? fs::relative(path, sourceDir()).string()
                                                                        : fs::relative(path, sharedDir()).string();
  std::string name;
  for (char c : rel.substr(0, rel.size() - 5)) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Shared, Corpus, ::testing::ValuesIn(corpusFiles()), testName);

TEST(CorpusWalk, FindsTheWholeCorpus) {
  // 81 corpus documents, 33 reference documents and our examples at the time of writing: a
  // walk that silently found nothing would pass every test above.
  EXPECT_GE(corpusFiles().size(), 117u);
}

}  // namespace
}  // namespace mxc::test
