// Golden IR dumps: the IR text of every corpus document (after the passes, with effects) is
// committed under generated/ir/ and compared here. `scripts/update-goldens` rewrites them
// (this test with MXC_UPDATE_GOLDENS=1); review the diff before committing.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "compiler/ir/Effects.h"
#include "compiler/ir/Print.h"
#include "compiler/ir/passes/Pass.h"
#include "compiler/lower/Lowering.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

/// Corpus documents, relative to the shared folder (so dumps hold no machine paths).
std::vector<std::string> corpusDocuments() {
  std::vector<std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(sharedDir() / "corpus")) {
    if (e.path().extension() == ".mtlx") files.push_back(fs::relative(e.path(), sharedDir()).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// The IR dump of a document: each material's tree, or the errors that stopped it.
std::string dump(const std::string& relative) {
  Context context;
  const doc::Document* d = context.loader.loadFile(relative);
  if (!d) return context.diagnostics.format();
  resolve::ResolvedDocument r = resolve::resolveDocument(*d, context.libraries.top(), context.diagnostics);
  std::vector<ir::Material> materials = lower::lowerDocument(r, {}, context.diagnostics);
  std::string out = "# mxc inspect --ir " + relative + "\n";
  for (ir::Material& m : materials) {
    ir::runPasses(m);
    ir::summarizeEffects(m);
    out += "\n" + ir::printMaterial(m, &d->source());
  }
  if (context.diagnostics.hasErrors()) out += "\n" + context.diagnostics.format();
  return out;
}

class IrGolden : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    // Documents are opened relative to the shared folder: their paths in the dump are portable.
    ASSERT_EQ(::chdir(sharedDir().c_str()), 0);
  }
};

TEST_P(IrGolden, MatchesCommittedDump) {
  const std::string relative = GetParam();
  fs::path golden = sourceDir() / "generated/ir" / fs::path(relative).replace_extension(".txt");
  const std::string actual = dump(relative);
  if (const char* update = std::getenv("MXC_UPDATE_GOLDENS"); update && std::string(update) == "1") {
    fs::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << actual;
    GTEST_SKIP() << "updated " << golden;
  }
  std::ifstream in(golden, std::ios::binary);
  ASSERT_TRUE(in) << "no golden dump " << golden << ": run scripts/update-goldens";
  std::stringstream expected;
  expected << in.rdbuf();
  EXPECT_EQ(actual, expected.str()) << "the IR of " << relative << " changed; if that is intended, run "
                                    << "scripts/update-goldens and review the diff of generated/ir/";
}

INSTANTIATE_TEST_SUITE_P(Corpus, IrGolden, ::testing::ValuesIn(corpusDocuments()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = fs::path(param.param).replace_extension("").string();
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(IrGoldenFiles, NoStaleDumps) {
  // Every committed dump belongs to a corpus document (a renamed document leaves none behind).
  std::set<std::string> expected;
  for (const std::string& doc : corpusDocuments()) expected.insert(fs::path(doc).replace_extension(".txt").string());
  for (const auto& e : fs::recursive_directory_iterator(sourceDir() / "generated/ir")) {
    if (!e.is_regular_file()) continue;
    std::string rel = fs::relative(e.path(), sourceDir() / "generated/ir").string();
    EXPECT_TRUE(expected.count(rel)) << "stale golden dump generated/ir/" << rel;
  }
}

}  // namespace
}  // namespace mxc::test
