// Golden IR dumps: the IR text of every corpus document (after the passes, with effects) is
// committed under generated/ir/ and compared here. `scripts/update-goldens` rewrites them
// (this test with MXC_UPDATE_GOLDENS=1); review the diff before committing.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "compiler/driver/Compiler.h"
#include "compiler/ir/Print.h"
#include "support/TestSupport.h"

namespace mxc::test {
namespace {

namespace fs = std::filesystem;

/// The IR dump of a document: each material's tree, or the errors that stopped it.
std::string dump(const std::string& relative) {
  Context context;
  CompileRequest request;
  request.document = relative;
  request.partial = true;  // what lowers of a document with errors, then the errors
  Compiler compiler(context, request);
  const doc::Document* d = compiler.document();
  if (!d) return context.diagnostics.format();
  std::string out = "# mxc inspect --ir " + relative + "\n";
  for (const ir::Material& m : compiler.materials()) out += "\n" + ir::printMaterial(m, &d->source());
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
