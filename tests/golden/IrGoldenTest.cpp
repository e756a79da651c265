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
  matchGolden(golden, dump(relative), "generated/ir/");
}

INSTANTIATE_TEST_SUITE_P(Corpus, IrGolden, ::testing::ValuesIn(corpusDocuments()),
                         corpusTestName);

TEST(IrGoldenFiles, NoStaleDumps) {
  for (const std::string& rel : staleGoldens(sourceDir() / "generated/ir", ".txt")) {
    ADD_FAILURE() << "stale golden dump generated/ir/" << rel;
  }
}

}  // namespace
}  // namespace mxc::test
