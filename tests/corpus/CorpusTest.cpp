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

/// A library stack loaded once for the whole test program.
struct Libraries {
  SourceManager sources;
  Diagnostics diagnostics;
  lib::LibraryStack stack{sources, diagnostics};
};

enum class LibraryChoice { Builtin, MaterialX, Both };

const lib::NodeLibrary& libraryFor(LibraryChoice choice) {
  static Libraries builtin, materialx, both;
  static bool loaded = false;
  if (!loaded) {
    loaded = true;
    const fs::path mx = sharedDir() / "reference/materialx/libraries";
    builtin.stack.addBuiltin();
    materialx.stack.addFolder(mx);
    both.stack.addBuiltin();
    both.stack.addFolder(mx);
    for (Libraries* l : {&builtin, &materialx, &both}) {
      EXPECT_FALSE(l->diagnostics.hasErrors()) << l->diagnostics.format();
    }
  }
  return choice == LibraryChoice::Builtin ? builtin.stack.top() : choice == LibraryChoice::MaterialX ? materialx.stack.top() : both.stack.top();
}

class Corpus : public ::testing::TestWithParam<std::string> {
 protected:
  void check(LibraryChoice choice) {
    SourceManager sources;
    Diagnostics diagnostics;
    doc::DocumentLoader loader(sources, diagnostics);
    const doc::Document* d = loader.loadFile(GetParam());
    ASSERT_NE(d, nullptr) << diagnostics.format();
    resolve::ResolvedDocument r = resolve::resolveDocument(*d, libraryFor(choice), diagnostics);
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.format();
    // Material documents (examples and presets) bind a shader to each material.
    const std::string& path = GetParam();
    if (path.find("examples/") != std::string::npos || path.find("openpbr-presets") != std::string::npos) {
      EXPECT_FALSE(r.materials.empty());
      for (const auto& m : r.materials) EXPECT_FALSE(m.shaders.empty()) << m.node->name();
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
